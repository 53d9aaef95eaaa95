package main

import (
	"encoding/binary"
	"path/filepath"
	"reflect"
	"sort"
	"testing"

	k "osdk-conformance.local/generated/go/osdk_kaitai"
)

func testTables(t *testing.T) *Tables {
	t.Helper()
	tb, err := loadTables(filepath.Join("..", "..", "..", "generated", "tables", "osdk_tables.json"))
	if err != nil {
		t.Fatal(err)
	}
	return tb
}

// frame builds a plain frame with good CRCs around data (nil: header only).
func frame(session byte, seq uint16, data []byte) []byte {
	n := k.HeaderLen
	if data != nil {
		n += len(data) + 4
	}
	f := make([]byte, k.HeaderLen, n)
	f[0] = 0xAA
	binary.LittleEndian.PutUint16(f[1:], uint16(n))
	f[3] = session
	binary.LittleEndian.PutUint16(f[8:], seq)
	binary.LittleEndian.PutUint16(f[10:], k.Crc16(f[:10]))
	if data != nil {
		f = append(f, data...)
		f = binary.LittleEndian.AppendUint32(f, k.Crc32(f))
	}
	return f
}

type brief struct {
	kind   k.EventKind
	offset int
	error  string
	length int
}

func deframeAll(data []byte, sizes []int) []brief {
	d := k.NewDeframer()
	var evs []k.Event
	for _, c := range splitChunks(data, sizes) {
		evs = append(evs, d.Feed(c)...)
	}
	evs = append(evs, d.Finish()...)
	out := make([]brief, len(evs))
	for i, e := range evs {
		out[i] = brief{e.Kind, e.Offset, "", e.Length}
		if e.Err != nil {
			out[i].error = e.Err.Class
		}
	}
	return out
}

// The library's receiver as decode_stream uses it: resync after a bad
// header and a bad CRC-32, chunk-independent.
func TestDeframerResync(t *testing.T) {
	good := frame(2, 7, []byte{0x01, 0x03, 0xAA, 0x55})
	short := frame(0, 1, nil)
	// A frame whose CRC-32 is wrong and which hides a good header-only frame.
	outer := frame(2, 8, append(append([]byte{0x00, 0x00}, short...), 0x00))
	outer[len(outer)-1] ^= 0xFF

	var in []byte
	in = append(in, 0x01, 0x02)              // garbage
	in = append(in, 0xAA, 0x00)              // a start byte with no header behind it
	in = append(in, good...)                 // offset 4
	in = append(in, outer...)                // offset 4+20
	in = append(in, good[:k.HeaderLen+2]...) // a truncated tail
	o := 4 + len(good)
	h := k.HeaderLen
	want := []brief{
		{k.EventGarbage, 0, "", 2},
		{k.EventError, 2, "bad_crc16", 1},
		{k.EventGarbage, 3, "", 1},
		{k.EventFrame, 4, "", len(good)},
		{k.EventError, o, "bad_crc32", len(outer)},
		// rescanning after the rejected start byte: the rest of its header
		// and two value bytes, then the frame hidden in its value
		{k.EventGarbage, o + 1, "", h + 1},
		{k.EventFrame, o + h + 2, "", h},
		{k.EventGarbage, o + 2*h + 2, "", len(outer) - 2*h - 2},
		{k.EventError, o + len(outer), "truncated_frame", h + 2},
		{k.EventGarbage, o + len(outer) + 1, "", h + 1},
	}

	for _, sizes := range [][]int{nil, {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1}, {5, 0, 30, 3}} {
		got := deframeAll(in, sizes)
		if !reflect.DeepEqual(got, want) {
			t.Errorf("chunks %v:\n got %v\nwant %v", sizes, got, want)
		}
	}
}

func TestSplitChunks(t *testing.T) {
	got := splitChunks([]byte{1, 2, 3, 4, 5}, []int{2, 0, 1 << 62, 3})
	want := [][]byte{{1, 2}, {}, {3, 4, 5}, {}}
	if !reflect.DeepEqual(got, want) {
		t.Errorf("got %v, want %v", got, want)
	}
}

// Every ksy type of the tables has its generated Go struct in k.Types (that
// list compiling shows the Kaitai compiler gave each type the name the
// tables' class path says), with a Go field for every field the model shows.
func TestRegistryCoversTables(t *testing.T) {
	tb := testTables(t)
	var fromGo, fromTables []string
	for _, gt := range k.Types {
		fromGo = append(fromGo, gt.Name())
		key, ok := tb.typeByClass[gt.Name()]
		if !ok {
			continue
		}
		for _, f := range tb.Model.Types[key].Fields {
			if _, ok := gt.FieldByName(camel(f.ID)); !ok {
				t.Errorf("%s: no Go field %s", key, camel(f.ID))
			}
		}
	}
	for name := range tb.typeByClass {
		fromTables = append(fromTables, name)
	}
	sort.Strings(fromGo)
	sort.Strings(fromTables)
	if !reflect.DeepEqual(fromGo, fromTables) {
		t.Errorf("k.Types %v\n   tables types %v", fromGo, fromTables)
	}
}

func TestEvalCondition(t *testing.T) {
	type parent struct{ IsAck bool }
	type child struct {
		Len     uint64
		HasMode bool
		_parent *parent
	}
	obj := &child{Len: 20, _parent: &parent{IsAck: true}}
	for expr, want := range map[string]bool{
		"len > 12": true, "len > 20": false, "has_mode": false, "not has_mode": true,
		"_parent.is_ack": true, "not _parent.is_ack": false,
		"(len >= 0x14) and not (has_mode or false)": true,
	} {
		got, err := evalCondition(expr, reflect.ValueOf(obj))
		if err != nil || got != want {
			t.Errorf("%s: got %v, %v; want %v", expr, got, err, want)
		}
	}
	if _, err := evalCondition("len + 1", reflect.ValueOf(obj)); err == nil {
		t.Error("len + 1: accepted")
	}
}
