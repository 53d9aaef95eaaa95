// Command libcheck answers tests/test_lib_go.py: one JSON request per line
// on standard input, one JSON answer per line, so that the test compares
// the library's encoders, errors and absent items with the reference. It
// is not an example.
package main

import (
	"bufio"
	"encoding/hex"
	"encoding/json"
	"errors"
	"fmt"
	"io"
	"math"
	"os"

	osdk "osdk-conformance.local/generated/go/osdk_kaitai"
)

type request struct {
	Op         string   `json:"op"`
	Mode       uint8    `json:"mode"`
	Bits       []uint32 `json:"bits"`
	AppID      uint32   `json:"app_id"`
	APILevel   uint32   `json:"api_level"`
	SDKVersion uint32   `json:"sdk_version"`
	BundleID   string   `json:"bundle_id"`
	Codes      []uint8  `json:"codes"`
	Byte       uint8    `json:"byte"`
	CmdSet     uint8    `json:"cmd_set"`
	CmdID      uint8    `json:"cmd_id"`
	IsAck      bool     `json:"is_ack"`
	Session    uint8    `json:"session"`
	Seq        uint16   `json:"seq"`
	Hex        string   `json:"hex"`
	Profile    string   `json:"profile"`
}

func main() {
	in := bufio.NewScanner(os.Stdin)
	in.Buffer(make([]byte, 1<<20), 1<<20)
	out := json.NewEncoder(os.Stdout)
	for in.Scan() {
		var r request
		if err := json.Unmarshal(in.Bytes(), &r); err != nil {
			fmt.Fprintln(os.Stderr, "libcheck:", err)
			os.Exit(2)
		}
		if err := out.Encode(answer(r)); err != nil {
			fmt.Fprintln(os.Stderr, "libcheck:", err)
			os.Exit(1)
		}
	}
}

func hexOf(b []byte) string { return hex.EncodeToString(b) }

func errorAnswer(err error) map[string]any {
	var e *osdk.Error
	return map[string]any{
		"error":    err.Error(),
		"is_error": errors.As(err, &e),
		"class":    classOf(e),
		"field":    fieldOf(e),
		"eof":      errors.Is(err, io.ErrUnexpectedEOF),
		"argument": errors.Is(err, osdk.ErrInvalidArgument),
	}
}

func classOf(e *osdk.Error) any {
	if e == nil {
		return nil
	}
	return e.Class
}

func fieldOf(e *osdk.Error) any {
	if e == nil {
		return nil
	}
	return e.Field
}

func answer(r request) map[string]any {
	data, _ := hex.DecodeString(r.Hex)
	switch r.Op {
	case "movement_control":
		b := r.Bits
		f := func(i int) float32 { return math.Float32frombits(b[i]) }
		return map[string]any{
			"bits":  hexOf(osdk.EncodeMovementControlBits(r.Mode, b[0], b[1], b[2], b[3])),
			"float": hexOf(osdk.EncodeMovementControl(r.Mode, f(0), f(1), f(2), f(3))),
		}
	case "activation":
		var id [32]byte
		raw, _ := hex.DecodeString(r.BundleID)
		copy(id[:], raw)
		return map[string]any{"hex": hexOf(osdk.EncodeActivation(r.AppID, r.APILevel, r.SDKVersion, id))}
	case "set_frequency":
		var codes [16]uint8
		copy(codes[:], r.Codes)
		return map[string]any{"hex": hexOf(osdk.EncodeSetFrequency(codes))}
	case "version_query":
		return map[string]any{"hex": hexOf(osdk.EncodeVersionQuery(r.Byte))}
	case "control_authority":
		return map[string]any{"hex": hexOf(osdk.EncodeControlAuthority(r.Byte))}
	case "frame":
		raw, err := osdk.EncodeFrame(r.CmdSet, r.CmdID, r.IsAck, r.Session, r.Seq, data)
		if err != nil {
			return errorAnswer(err)
		}
		return map[string]any{"hex": hexOf(raw)}
	case "decode_frame":
		f, err := osdk.DecodeFrame(data, r.Profile)
		if err != nil {
			return errorAnswer(err)
		}
		return broadcast(f, r.Profile)
	}
	return map[string]any{"error": "unknown op " + r.Op}
}

// broadcast reports every item of every profile through Item (an untyped
// nil when absent) and the scalar items through their accessors.
func broadcast(f *osdk.OsdkFrame, profile string) map[string]any {
	bc := osdk.BroadcastOf(f)
	if bc == nil {
		return map[string]any{"broadcast": false}
	}
	items := map[string]any{}
	for _, p := range osdk.Profiles {
		for _, name := range osdk.BroadcastItems(p) {
			items[name] = bc.Item(name) != nil
		}
	}
	out := map[string]any{"broadcast": true, "items": items, "battery": nil, "flight_status": nil}
	if v := bc.Battery(); v != nil {
		out["battery"] = *v
	}
	if v := bc.FlightStatus(); v != nil {
		out["flight_status"] = *v
	}
	return out
}
