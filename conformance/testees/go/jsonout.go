package main

import (
	"encoding/hex"
	"encoding/json"
	"math"
	"strconv"
	"strings"
)

// The value model keeps keys in wire order, so answers are built from Obj
// (an ordered object) and written by writeJSON rather than encoding/json.

type KV struct {
	Key string
	Val any
}

type Obj []KV

func (o Obj) Get(key string) (any, bool) {
	for _, kv := range o {
		if kv.Key == key {
			return kv.Val, true
		}
	}
	return nil, false
}

// Number is JSON number text, already formatted.
type Number string

func writeJSON(b *strings.Builder, v any) {
	switch x := v.(type) {
	case nil:
		b.WriteString("null")
	case Obj:
		b.WriteByte('{')
		for i, kv := range x {
			if i > 0 {
				b.WriteString(", ")
			}
			writeString(b, kv.Key)
			b.WriteString(": ")
			writeJSON(b, kv.Val)
		}
		b.WriteByte('}')
	case []any:
		b.WriteByte('[')
		for i, e := range x {
			if i > 0 {
				b.WriteString(", ")
			}
			writeJSON(b, e)
		}
		b.WriteByte(']')
	case string:
		writeString(b, x)
	case bool:
		b.WriteString(strconv.FormatBool(x))
	case int:
		b.WriteString(strconv.Itoa(x))
	case int64:
		b.WriteString(strconv.FormatInt(x, 10))
	case uint64:
		b.WriteString(strconv.FormatUint(x, 10))
	case Number:
		b.WriteString(string(x))
	default:
		panic("writeJSON: no JSON form for this value") // a bug of ours: internal_error
	}
}

func writeString(b *strings.Builder, s string) {
	text, _ := json.Marshal(s) // a string always marshals
	b.Write(text)
}

func hexString(data []byte) string {
	return hex.EncodeToString(data)
}

// readableFloat is the model's "value": a number printed the way Python's
// repr prints a double (what the other implementations show), or one of
// the strings "NaN", "Infinity", "-Infinity".
func readableFloat(v float64) any {
	switch {
	case math.IsNaN(v):
		return "NaN"
	case math.IsInf(v, 1):
		return "Infinity"
	case math.IsInf(v, -1):
		return "-Infinity"
	}
	a := math.Abs(v)
	if a != 0 && (a < 1e-4 || a >= 1e16) {
		return Number(strconv.FormatFloat(v, 'e', -1, 64))
	}
	s := strconv.FormatFloat(v, 'f', -1, 64)
	if !strings.ContainsAny(s, ".") {
		s += ".0"
	}
	return Number(s)
}

func float32Model(bits uint32) Obj {
	return Obj{{"f32", "0x" + leftPad(strconv.FormatUint(uint64(bits), 16), 8)},
		{"value", readableFloat(float64(math.Float32frombits(bits)))}}
}

func float64Model(bits uint64) Obj {
	return Obj{{"f64", "0x" + leftPad(strconv.FormatUint(bits, 16), 16)},
		{"value", readableFloat(math.Float64frombits(bits))}}
}

func leftPad(s string, n int) string {
	if len(s) >= n {
		return s
	}
	return strings.Repeat("0", n-len(s)) + s
}
