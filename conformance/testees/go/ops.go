package main

import (
	"bytes"
	"encoding/hex"
	"errors"
	"fmt"
	"math"
	"regexp"
	"strconv"
	"strings"

	"github.com/kaitai-io/kaitai_struct_go_runtime/kaitai"

	k "osdk-conformance.local/generated/go/osdk_kaitai"
)

const (
	testeeName = "osdk-kaitai-go"
	// sessions firstAckSession..lastAckSession have an ACK slot (PROTOCOL.md "ACK matching", ERRATA E32)
	firstAckSession = 2
	lastAckSession  = 31
)

var operations = []string{"decode_stream", "decode_frame", "decode_payload", "classify_control_mode", "check_movement_control",
	"encode_movement_control", "encode_frame"}

// The range of each movement-control setpoint, by field.
var axisRange = []struct{ axis, which string }{
	{"x", "horizontal"}, {"y", "horizontal"}, {"z", "vertical"}, {"yaw", "yaw"},
}

// Testee answers requests with the generated library (deframer, decoding,
// errors, encoders) and the tables (value model, control modes).
type Testee struct {
	tb    *Tables
	model Modeler
}

func NewTestee(tb *Tables) (*Testee, error) {
	return &Testee{tb: tb, model: Modeler{tb}}, nil
}

// reject is a rejection of the testee's own checks (check_movement_control).
func reject(class, format string, args ...any) *k.Error {
	return &k.Error{Class: class, Detail: fmt.Sprintf(format, args...)}
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
	i, err := r.intArg(key, 0xFF)
	return uint8(i), err
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

func stream(data []byte) *kaitai.Stream {
	return kaitai.NewStream(bytes.NewReader(data))
}

func (t *Testee) parsePayload(data []byte, cmdSet, cmdID uint8, isAck bool, profile string) (*k.OsdkPayload, error) {
	return k.DecodePayload(data, cmdSet, cmdID, isAck, profile)
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

func (t *Testee) decodePayload(r request, profile string) (Obj, error) {
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
	obj, err := t.parsePayload(data, cmdSet, cmdID, isAck, profile)
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

func (t *Testee) classify(r request, profile string) (Obj, error) {
	b, err := r.byteArg("byte")
	if err != nil {
		return nil, err
	}
	cm := k.NewOsdkControlMode()
	if err := cm.Read(stream([]byte{b}), nil, cm); err != nil {
		return nil, fmt.Errorf("control mode byte 0x%02x: %w", b, err)
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

func (t *Testee) checkMovementControl(r request, profile string) (Obj, error) {
	data, err := r.hexBytes()
	if err != nil {
		return nil, err
	}
	// As a command value: payload (0x01, 0x03) is osdk_movement_control plus
	// the check that no bytes trail it.
	obj, err := t.parsePayload(data, k.CommandMovementControl.CmdSet, k.CommandMovementControl.CmdID, false, profile)
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

func (t *Testee) decodeFrame(r request, profile string) (Obj, error) {
	data, err := r.hexBytes()
	if err != nil {
		return nil, err
	}
	f, err := k.DecodeFrame(data, profile)
	if err != nil {
		return nil, err
	}
	m, err := t.model.Object(f)
	if err != nil {
		return nil, err
	}
	return Obj{{"frame", m}}, nil
}

// f32Arg is a float argument {"f32": "0x…"}: its bits, never a float64.
func (r request) f32Arg(key string) (uint32, error) {
	v, err := r.arg(key)
	if err != nil {
		return 0, err
	}
	m, ok := v.(map[string]any)
	if !ok {
		return 0, badf("argument %q must be {\"f32\": \"0x…\"}", key)
	}
	s, ok := m["f32"].(string)
	if !ok || !strings.HasPrefix(s, "0x") || len(s) < 3 || len(s) > 10 {
		return 0, badf("argument %q must be {\"f32\": \"0x…\"} with up to 8 hex digits", key)
	}
	bits, err := strconv.ParseUint(s[2:], 16, 32)
	if err != nil {
		return 0, badf("argument %q: %q is not hex", key, s)
	}
	return uint32(bits), nil
}

func (r request) intArg(key string, top int64) (int64, error) {
	v, err := r.arg(key)
	if err != nil {
		return 0, err
	}
	i, err := integer(key, v)
	if err != nil {
		return 0, err
	}
	if i < 0 || i > top {
		return 0, badf("argument %q must be 0..%d", key, top)
	}
	return i, nil
}

func (t *Testee) encodeMovementControl(r request, _ string) (Obj, error) {
	mode, err := r.byteArg("mode")
	if err != nil {
		return nil, err
	}
	var bits [4]uint32
	for i, axis := range []string{"x", "y", "z", "yaw"} {
		if bits[i], err = r.f32Arg(axis); err != nil {
			return nil, err
		}
	}
	return Obj{{"hex", hexString(k.EncodeMovementControlBits(mode, bits[0], bits[1], bits[2], bits[3]))}}, nil
}

func (t *Testee) encodeFrame(r request, _ string) (Obj, error) {
	isAck, err := r.boolean("is_ack")
	if err != nil {
		return nil, err
	}
	var cmdSet, cmdID uint8
	if !isAck {
		if cmdSet, err = r.byteArg("cmd_set"); err != nil {
			return nil, err
		}
		if cmdID, err = r.byteArg("cmd_id"); err != nil {
			return nil, err
		}
	}
	session, err := r.intArg("session", 31)
	if err != nil {
		return nil, err
	}
	seq, err := r.intArg("seq", 0xFFFF)
	if err != nil {
		return nil, err
	}
	s, err := r.str("value")
	if err != nil {
		return nil, err
	}
	if !hexText.MatchString(s) {
		return nil, badf("argument 'value' is not a hex string of whole bytes")
	}
	value, _ := hex.DecodeString(s)
	raw, err := k.EncodeFrame(cmdSet, cmdID, isAck, uint8(session), uint16(seq), value)
	if err != nil {
		if errors.Is(err, k.ErrInvalidArgument) {
			return nil, badf("%v", err)
		}
		return nil, err
	}
	return Obj{{"hex", hexString(raw)}}, nil
}

// ---- streams ----------------------------------------------------------------------

// ackSlot is the command waiting for its ACK in one session.
type ackSlot struct {
	waiting       bool
	seq           uint16
	cmdSet, cmdID uint8
}

// streamDecoder turns Deframer events into answer events: Kaitai values,
// and ACKs typed by the command waiting in their session's slot with their
// SEQ (one slot per session 2..31: a plain command takes its session's
// slot, a matching ACK, header-only too, empties it). Without models,
// values stay as the parsers returned them (the bench mode times decoding,
// not the value model).
type streamDecoder struct {
	t       *Testee
	profile string
	models  bool
	slots   [lastAckSession + 1]ackSlot
}

func (d *streamDecoder) event(ev k.Event) (out Obj) {
	switch ev.Kind {
	case k.EventGarbage:
		return Obj{{"offset", ev.Offset}, {"kind", "garbage"}, {"length", ev.Length}}
	case k.EventError:
		return Obj{{"offset", ev.Offset}, {"kind", "error"}, {"error", ev.Err.Class}, {"detail", ev.Err.Detail}, {"length", ev.Length}}
	}
	defer func() { // our bug must not cost the rest of the stream
		if p := recover(); p != nil {
			out = d.errorEvent(ev, reject("undecodable", "internal error (panic: %v)", p), nil)
		}
	}()
	out, err := d.frame(ev)
	if err != nil {
		var rej *k.Error
		if !errors.As(err, &rej) {
			rej = reject("undecodable", "internal error (%v)", err)
		}
		return d.errorEvent(ev, rej, nil)
	}
	return out
}

func (d *streamDecoder) errorEvent(ev k.Event, r *k.Error, ackOf any) Obj {
	out := Obj{{"offset", ev.Offset}, {"kind", "error"}, {"error", r.Class}, {"detail", r.Detail}, {"length", ev.Length}}
	if ackOf != nil {
		out = append(out, KV{"ack_of", ackOf})
	}
	return out
}

func (d *streamDecoder) frame(ev k.Event) (Obj, error) {
	f, err := k.DecodeFrame(ev.Raw, d.profile)
	if err != nil {
		return nil, err
	}
	out := Obj{{"offset", ev.Offset}, {"kind", "frame"}}
	fd, plain := f.Data.(*k.OsdkFrame_FrameData)
	plain = plain && f.Len > k.HeaderLen
	headerOnly := f.Len == k.HeaderLen
	hasSlot := f.Session >= firstAckSession && f.Session <= lastAckSession
	if f.IsAck && (plain || headerOnly) && hasSlot {
		slot := &d.slots[f.Session]
		if slot.waiting && slot.seq == f.Seq {
			slot.waiting = false
			ackOf := commandName(slot.cmdSet, slot.cmdID)
			out = append(out, KV{"ack_of", ackOf})
			value := []byte{} // a header-only ACK's value is empty
			if plain {
				value = fd.AckValue
			}
			ack, err := d.t.parsePayload(value, slot.cmdSet, slot.cmdID, true, d.profile)
			if err != nil {
				var rej *k.Error
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
	} else if !f.IsAck && plain && hasSlot {
		d.slots[f.Session] = ackSlot{true, f.Seq, uint8(fd.CmdSet), fd.CmdId}
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
	deframer *k.Deframer
	dec      *streamDecoder
	onEvent  func(Obj)
}

func (t *Testee) newEventStream(p string, models bool, onEvent func(Obj)) *eventStream {
	dec := &streamDecoder{t: t, profile: p, models: models}
	return &eventStream{deframer: k.NewDeframer(), dec: dec, onEvent: onEvent}
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

func (t *Testee) decodeStream(r request, p string) (Obj, error) {
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

type operation func(t *Testee, r request, profile string) (Obj, error)

var ops = map[string]operation{
	"decode_stream":           (*Testee).decodeStream,
	"decode_frame":            (*Testee).decodeFrame,
	"decode_payload":          (*Testee).decodePayload,
	"classify_control_mode":   (*Testee).classify,
	"check_movement_control":  (*Testee).checkMovementControl,
	"encode_movement_control": (*Testee).encodeMovementControl,
	"encode_frame":            (*Testee).encodeFrame,
}

// The operations whose requests carry no profile.
var withoutProfile = map[string]bool{"encode_movement_control": true, "encode_frame": true}

// answer is the response to one request; an error is a bad request
// (badRequest) or a bug of ours.
func (t *Testee) answer(r request) (Obj, error) {
	op, ok := r["op"].(string)
	if !ok {
		return nil, badf(`a request is a JSON object with an "op" string`)
	}
	if op == "capabilities" {
		profiles := make([]any, len(k.Profiles))
		for i, p := range k.Profiles {
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
	if !known || (!withoutProfile[op] && !knownProfile(profile)) {
		return Obj{{"ok", false}, {"unsupported", true}}, nil
	}
	result, err := fn(t, r, profile)
	if err != nil {
		var rej *k.Error
		if errors.As(err, &rej) {
			return Obj{{"ok", false}, {"error", rej.Class}, {"detail", rej.Detail}}, nil
		}
		return nil, err
	}
	return Obj{{"ok", true}, {"result", result}}, nil
}

func knownProfile(name string) bool {
	_, err := k.ProfileOf(name)
	return err == nil
}

// commandName is ack_of's name of a command: "unknown" for one the spec does not name.
func commandName(cmdSet, cmdID uint8) string {
	if n := k.CommandName(cmdSet, cmdID); n != "" {
		return n
	}
	return "unknown"
}

// splitChunks cuts data into reads of the given sizes; what they leave over
// is one last read (sizes past the end give empty reads).
func splitChunks(data []byte, sizes []int) [][]byte {
	var out [][]byte
	pos := 0
	for _, size := range sizes {
		end := len(data)
		if size < end-pos {
			end = pos + size
		}
		out = append(out, data[pos:end])
		pos = end // clamped: a huge size must not overflow
	}
	if pos < len(data) {
		out = append(out, data[pos:])
	}
	return out
}
