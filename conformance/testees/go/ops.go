package main

import (
	"bytes"
	"container/list"
	"encoding/hex"
	"errors"
	"fmt"
	"math"
	"regexp"
	"strings"

	"github.com/kaitai-io/kaitai_struct_go_runtime/kaitai"

	k "osdk-conformance.local/generated/go/osdk_kaitai"
)

const (
	testeeName   = "osdk-kaitai-go"
	pendingLimit = 1024 // unanswered commands remembered for ACK matching
)

var operations = []string{"decode_stream", "decode_frame", "decode_payload", "classify_control_mode", "check_movement_control"}

// The range of each movement-control setpoint, by field.
var axisRange = []struct{ axis, which string }{
	{"x", "horizontal"}, {"y", "horizontal"}, {"z", "vertical"}, {"yaw", "yaw"},
}

// Testee answers requests with the generated parsers and the tables.
type Testee struct {
	tb    *Tables
	model Modeler
	sums  Checksums
}

func NewTestee(tb *Tables) (*Testee, error) {
	crc16, err := NewCRC(tb.CRC["crc16"])
	if err != nil {
		return nil, err
	}
	crc32, err := NewCRC(tb.CRC["crc32"])
	if err != nil {
		return nil, err
	}
	return &Testee{tb: tb, model: Modeler{tb}, sums: Checksums{crc16, crc32}}, nil
}

// badRequest is input the testee cannot use (answered bad_request).
type badRequest struct{ msg string }

func (e badRequest) Error() string { return e.msg }

func badf(format string, args ...any) error { return badRequest{fmt.Sprintf(format, args...)} }

// ---- arguments ----------------------------------------------------------------

type request map[string]any

func (r request) arg(key string) (any, error) {
	v, ok := r[key]
	if !ok {
		return nil, badf("missing argument %q", key)
	}
	return v, nil
}

func (r request) str(key string) (string, error) {
	v, err := r.arg(key)
	if err != nil {
		return "", err
	}
	s, ok := v.(string)
	if !ok {
		return "", badf("argument %q has the wrong type (%T)", key, v)
	}
	return s, nil
}

func (r request) boolean(key string) (bool, error) {
	v, err := r.arg(key)
	if err != nil {
		return false, err
	}
	b, ok := v.(bool)
	if !ok {
		return false, badf("argument %q has the wrong type (%T)", key, v)
	}
	return b, nil
}

// integer accepts a JSON integer only (not 1.0, not true), like Python's int.
func integer(key string, v any) (int64, error) {
	n, ok := v.(jsonNumber)
	if !ok || strings.ContainsAny(string(n), ".eE") {
		return 0, badf("argument %q must be an integer", key)
	}
	i, err := n.Int64()
	if err != nil {
		if !strings.HasPrefix(string(n), "-") {
			return math.MaxInt64, nil // beyond any range that matters
		}
		return math.MinInt64, nil
	}
	return i, nil
}

func (r request) byteArg(key string) (uint8, error) {
	v, err := r.arg(key)
	if err != nil {
		return 0, err
	}
	i, err := integer(key, v)
	if err != nil {
		return 0, err
	}
	if i < 0 || i > 0xFF {
		return 0, badf("argument %q must be 0..255", key)
	}
	return uint8(i), nil
}

var hexText = regexp.MustCompile(`^(?:[0-9a-fA-F]{2})*$`)

func (r request) hexBytes() ([]byte, error) {
	s, err := r.str("hex")
	if err != nil {
		return nil, err
	}
	if !hexText.MatchString(s) {
		return nil, badf("argument 'hex' is not a hex string of whole bytes")
	}
	return hex.DecodeString(s)
}

// profile is the value the generated parsers take for a profile id.
func (t *Testee) profile(name string) (k.OsdkPayload_Profile, bool) {
	n, ok := t.tb.ProfileValues[name]
	return k.OsdkPayload_Profile(n), ok
}

// ---- parsing ----------------------------------------------------------------------

func stream(data []byte) *kaitai.Stream {
	return kaitai.NewStream(bytes.NewReader(data))
}

func (t *Testee) parsePayload(data []byte, cmdSet, cmdID uint8, isAck bool, p k.OsdkPayload_Profile) (*k.OsdkPayload, error) {
	obj := k.NewOsdkPayload(cmdSet, cmdID, isAck, p)
	if err := obj.Read(stream(data), nil, obj); err != nil {
		return nil, t.tb.rejection(err)
	}
	return obj, nil
}

func (t *Testee) parseFrame(data []byte, p k.OsdkPayload_Profile) (*k.OsdkFrame, error) {
	obj := k.NewOsdkFrame(p)
	if err := obj.Read(stream(data), nil, obj); err != nil {
		return nil, t.tb.rejection(err)
	}
	return obj, nil
}

func (t *Testee) bodyModel(p *k.OsdkPayload) (any, error) {
	m, err := t.model.Object(p)
	if err != nil {
		return nil, err
	}
	body, ok := m.Get("body")
	if !ok {
		return nil, errors.New("payload model without a body")
	}
	return body, nil
}

// ---- operations ---------------------------------------------------------------------

func (t *Testee) decodePayload(r request, p k.OsdkPayload_Profile, _ string) (Obj, error) {
	data, err := r.hexBytes()
	if err != nil {
		return nil, err
	}
	cmdSet, err := r.byteArg("cmd_set")
	if err != nil {
		return nil, err
	}
	cmdID, err := r.byteArg("cmd_id")
	if err != nil {
		return nil, err
	}
	isAck, err := r.boolean("is_ack")
	if err != nil {
		return nil, err
	}
	obj, err := t.parsePayload(data, cmdSet, cmdID, isAck, p)
	if err != nil {
		return nil, err
	}
	body, err := t.bodyModel(obj)
	if err != nil {
		return nil, err
	}
	return Obj{{"value", body}}, nil
}

func (t *Testee) modeInfo(b uint8, profile string) (ModeInfo, error) {
	modes := t.tb.ControlModes[profile].Modes
	if int(b) >= len(modes) {
		return ModeInfo{}, fmt.Errorf("no control mode table for %s", profile)
	}
	return modes[b], nil
}

func combination(c *int) any {
	if c == nil {
		return nil
	}
	return *c
}

func (t *Testee) classify(r request, _ k.OsdkPayload_Profile, profile string) (Obj, error) {
	b, err := r.byteArg("byte")
	if err != nil {
		return nil, err
	}
	cm := k.NewOsdkControlMode()
	if err := cm.Read(stream([]byte{b}), nil, cm); err != nil {
		return nil, t.tb.rejection(err)
	}
	fields, err := t.model.Object(cm)
	if err != nil {
		return nil, err
	}
	c, err := t.modeInfo(b, profile)
	if err != nil {
		return nil, err
	}
	return Obj{{"fields", fields}, {"classification", c.Classification}, {"combination", combination(c.Combination)}}, nil
}

func (t *Testee) checkMovementControl(r request, p k.OsdkPayload_Profile, profile string) (Obj, error) {
	data, err := r.hexBytes()
	if err != nil {
		return nil, err
	}
	// As a command value: payload (0x01, 0x03) is osdk_movement_control plus
	// the check that no bytes trail it.
	obj, err := t.parsePayload(data, 0x01, 0x03, false, p)
	if err != nil {
		return nil, err
	}
	mc, ok := obj.Body.(*k.OsdkMovementControl)
	if !ok {
		return nil, fmt.Errorf("payload 0x0103 decoded as %T", obj.Body)
	}
	value, err := t.bodyModel(obj)
	if err != nil {
		return nil, err
	}
	c, err := t.modeInfo(data[0], profile)
	if err != nil {
		return nil, err
	}
	if c.Classification != "documented" || c.Combination == nil {
		return nil, reject("undefined_mode", "mode byte 0x%02x is %s on %s", data[0], c.Classification, profile)
	}
	ranges, ok := t.tb.ControlModes[profile].Ranges[fmt.Sprint(*c.Combination)]
	if !ok {
		return nil, fmt.Errorf("no ranges for combination %d on %s", *c.Combination, profile)
	}
	setpoints := map[string]float32{"x": mc.X, "y": mc.Y, "z": mc.Z, "yaw": mc.Yaw}
	for _, a := range axisRange {
		v := float64(setpoints[a.axis])
		lim, ok := ranges[a.which]
		if !ok {
			return nil, fmt.Errorf("no %s range for combination %d on %s", a.which, *c.Combination, profile)
		}
		if math.IsNaN(v) || math.IsInf(v, 0) || (lim.Min != nil && v < *lim.Min) || (lim.Max != nil && v > *lim.Max) {
			return nil, reject("out_of_range", "%s = %v outside the %s range %s..%s", a.axis, v, a.which, bound(lim.Min), bound(lim.Max))
		}
	}
	return Obj{{"value", value}, {"combination", *c.Combination}}, nil
}

func bound(b *float64) string {
	if b == nil {
		return "None"
	}
	return fmt.Sprint(*b)
}

func (t *Testee) decodeFrame(r request, p k.OsdkPayload_Profile, _ string) (Obj, error) {
	data, err := r.hexBytes()
	if err != nil {
		return nil, err
	}
	// The receiver's checks, in the order a receiver meets them.
	switch {
	case len(data) == 0:
		return nil, reject("truncated_frame", "no bytes")
	case data[0] != sof:
		return nil, reject("bad_sof", "first byte 0x%02x is not the start byte", data[0])
	case len(data) < headerLen:
		return nil, reject("truncated_frame", "%d bytes, less than a header", len(data))
	}
	if class, detail := t.sums.headerProblem(data[:headerLen]); class != "" {
		return nil, reject(class, "%s", detail)
	}
	length := frameLength(data)
	switch {
	case len(data) < length:
		return nil, reject("truncated_frame", "%d bytes of a frame of LEN %d", len(data), length)
	case len(data) > length:
		return nil, reject("length_mismatch", "%d bytes for LEN %d", len(data), length)
	}
	if length > headerLen {
		if bad, detail := t.sums.crc32Problem(data); bad {
			return nil, reject("bad_crc32", "%s", detail)
		}
	}
	f, err := t.parseFrame(data, p)
	if err != nil {
		return nil, err
	}
	m, err := t.model.Object(f)
	if err != nil {
		return nil, err
	}
	return Obj{{"frame", m}}, nil
}

// ---- streams ----------------------------------------------------------------------

type pendingKey struct{ session, seq uint64 }

type pendingCmd struct {
	key           pendingKey
	cmdSet, cmdID uint8
}

// streamDecoder turns Deframer events into answer events: Kaitai values,
// and ACKs typed by the command with the same session and SEQ seen earlier.
// Pending commands are kept in first-seen order (a repeated key keeps its
// place) and the oldest is forgotten beyond pendingLimit. Without models,
// values stay as the parsers returned them (the bench mode times decoding,
// not the value model).
type streamDecoder struct {
	t       *Testee
	profile k.OsdkPayload_Profile
	models  bool
	order   *list.List
	pending map[pendingKey]*list.Element
}

func (d *streamDecoder) event(ev Event) (out Obj) {
	switch ev.Kind {
	case EvGarbage:
		return Obj{{"offset", ev.Offset}, {"kind", "garbage"}, {"length", ev.Length}}
	case EvRejected:
		return Obj{{"offset", ev.Offset}, {"kind", "error"}, {"error", ev.Error}, {"detail", ev.Detail}, {"length", ev.Length}}
	}
	defer func() { // our bug must not cost the rest of the stream
		if p := recover(); p != nil {
			out = d.errorEvent(ev, reject("undecodable", "internal error (panic: %v)", p), nil)
		}
	}()
	out, err := d.frame(ev)
	if err != nil {
		var rej *Rejection
		if !errors.As(err, &rej) {
			rej = reject("undecodable", "internal error (%v)", err)
		}
		return d.errorEvent(ev, rej, nil)
	}
	return out
}

func (d *streamDecoder) errorEvent(ev Event, r *Rejection, ackOf any) Obj {
	out := Obj{{"offset", ev.Offset}, {"kind", "error"}, {"error", r.Class}, {"detail", r.Detail}, {"length", len(ev.Raw)}}
	if ackOf != nil {
		out = append(out, KV{"ack_of", ackOf})
	}
	return out
}

func (d *streamDecoder) frame(ev Event) (Obj, error) {
	f, err := d.t.parseFrame(ev.Raw, d.profile)
	if err != nil {
		return nil, err
	}
	out := Obj{{"offset", ev.Offset}, {"kind", "frame"}}
	if fd, ok := f.Data.(*k.OsdkFrame_FrameData); ok && f.Len > headerLen {
		key := pendingKey{f.Session, uint64(f.Seq)}
		if f.IsAck {
			if el, ok := d.pending[key]; ok {
				cmd := d.order.Remove(el).(pendingCmd)
				delete(d.pending, key)
				ackOf := d.t.tb.commandName(int(cmd.cmdSet), int(cmd.cmdID))
				out = append(out, KV{"ack_of", ackOf})
				ack, err := d.t.parsePayload(fd.AckValue, cmd.cmdSet, cmd.cmdID, true, d.profile)
				if err != nil {
					var rej *Rejection
					if errors.As(err, &rej) {
						return d.errorEvent(ev, rej, ackOf), nil
					}
					return nil, err
				}
				if !d.models {
					out = append(out, KV{"ack", ack.Body})
				} else if body, err := d.t.bodyModel(ack); err != nil {
					return nil, err
				} else {
					out = append(out, KV{"ack", body})
				}
			}
		} else if f.Session > 0 {
			cmd := pendingCmd{key, uint8(fd.CmdSet), fd.CmdId}
			if el, ok := d.pending[key]; ok {
				el.Value = cmd
			} else {
				d.pending[key] = d.order.PushBack(cmd)
				if d.order.Len() > pendingLimit {
					oldest := d.order.Remove(d.order.Front()).(pendingCmd)
					delete(d.pending, oldest.key)
				}
			}
		}
	}
	if !d.models {
		return append(out, KV{"frame", f}), nil
	}
	m, err := d.t.model.Object(f)
	if err != nil {
		return nil, err
	}
	return append(out, KV{"frame", m}), nil
}

// eventStream is decode_stream's loop: each read through the deframer and
// the stream decoder, each event to onEvent (also the bench mode's loop).
type eventStream struct {
	deframer *Deframer
	dec      *streamDecoder
	onEvent  func(Obj)
}

func (t *Testee) newEventStream(p k.OsdkPayload_Profile, models bool, onEvent func(Obj)) *eventStream {
	dec := &streamDecoder{t: t, profile: p, models: models, order: list.New(), pending: map[pendingKey]*list.Element{}}
	return &eventStream{deframer: NewDeframer(t.sums), dec: dec, onEvent: onEvent}
}

func (s *eventStream) Feed(chunk []byte) {
	for _, ev := range s.deframer.Feed(chunk) {
		s.onEvent(s.dec.event(ev))
	}
}

func (s *eventStream) Finish() {
	for _, ev := range s.deframer.Finish() {
		s.onEvent(s.dec.event(ev))
	}
}

func (t *Testee) decodeStream(r request, p k.OsdkPayload_Profile, _ string) (Obj, error) {
	data, err := r.hexBytes()
	if err != nil {
		return nil, err
	}
	v, err := r.arg("chunks")
	if err != nil {
		return nil, err
	}
	items, ok := v.([]any)
	if !ok {
		return nil, badf("argument 'chunks' has the wrong type (%T)", v)
	}
	sizes := make([]int, len(items))
	for i, s := range items {
		n, err := integer("chunks", s)
		if err != nil || n < 0 {
			return nil, badf("argument 'chunks' must be a list of non-negative integers")
		}
		sizes[i] = int(n)
	}
	events := []any{}
	stream := t.newEventStream(p, true, func(ev Obj) { events = append(events, ev) })
	for _, chunk := range splitChunks(data, sizes) {
		stream.Feed(chunk)
	}
	stream.Finish()
	return Obj{{"events", events}}, nil
}

// ---- dispatch -----------------------------------------------------------------------

type operation func(t *Testee, r request, p k.OsdkPayload_Profile, profile string) (Obj, error)

var ops = map[string]operation{
	"decode_stream":          (*Testee).decodeStream,
	"decode_frame":           (*Testee).decodeFrame,
	"decode_payload":         (*Testee).decodePayload,
	"classify_control_mode":  (*Testee).classify,
	"check_movement_control": (*Testee).checkMovementControl,
}

// answer is the response to one request; an error is a bad request
// (badRequest) or a bug of ours.
func (t *Testee) answer(r request) (Obj, error) {
	op, ok := r["op"].(string)
	if !ok {
		return nil, badf(`a request is a JSON object with an "op" string`)
	}
	if op == "capabilities" {
		profiles := make([]any, len(t.tb.Profiles))
		for i, p := range t.tb.Profiles {
			profiles[i] = p
		}
		opsList := make([]any, len(operations))
		for i, o := range operations {
			opsList[i] = o
		}
		return Obj{{"ok", true}, {"result", Obj{{"name", testeeName}, {"operations", opsList}, {"profiles", profiles}}}}, nil
	}
	fn, known := ops[op]
	profile, _ := r["profile"].(string)
	if !known || !t.knownProfile(profile) {
		return Obj{{"ok", false}, {"unsupported", true}}, nil
	}
	p, ok := t.profile(profile)
	if !ok {
		return nil, fmt.Errorf("profile %s has no value in the tables (profile_values)", profile)
	}
	result, err := fn(t, r, p, profile)
	if err != nil {
		var rej *Rejection
		if errors.As(err, &rej) {
			return Obj{{"ok", false}, {"error", rej.Class}, {"detail", rej.Detail}}, nil
		}
		return nil, err
	}
	return Obj{{"ok", true}, {"result", result}}, nil
}

func (t *Testee) knownProfile(name string) bool {
	for _, p := range t.tb.Profiles {
		if p == name {
			return true
		}
	}
	return false
}
