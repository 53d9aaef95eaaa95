package main

import (
	"bytes"
	"encoding/binary"
	"fmt"
)

// The receiver of osdk_conformance/core/deframe.py: hunt for 0xAA, check the
// 12-byte header (CRC-16 first, then VER, RES0, RES1, LEN) and on any
// failure drop that ONE byte and hunt again; with a good header wait for
// LEN bytes and check the CRC-32, rescanning from the byte after the start
// on failure so a good frame hidden inside a corrupt one is still found.
// Unlike the SDK, every rejection is reported.

const (
	sof       = 0xAA
	headerLen = 12
	crc32Len  = 4
	maxLen    = 0x3FF
)

type EventKind int

const (
	EvFrame EventKind = iota
	EvRejected
	EvGarbage
)

// Event is a frame (Raw), bytes the receiver dropped (Error, Detail,
// Length) or a run of Length bytes before any start byte.
type Event struct {
	Kind   EventKind
	Offset int
	Raw    []byte
	Error  string
	Detail string
	Length int
}

type Checksums struct {
	crc16, crc32 *CRC
}

func frameLength(header []byte) int {
	return int(binary.LittleEndian.Uint16(header[1:3]) & 0x3FF)
}

// headerProblem is the error class and detail of the first thing wrong with
// a 12-byte header, or "". CRC-16 comes first: when it fails, the values of
// the other fields mean nothing.
func (c Checksums) headerProblem(h []byte) (string, string) {
	stored := uint64(binary.LittleEndian.Uint16(h[10:12]))
	if computed := c.crc16.Sum(h[:10]); computed != stored {
		return "bad_crc16", fmt.Sprintf("CRC-16 is 0x%04x, expected 0x%04x", stored, computed)
	}
	word := binary.LittleEndian.Uint16(h[1:3])
	length, ver := int(word&0x3FF), word>>10
	switch {
	case ver != 0:
		return "bad_version", fmt.Sprintf("header version %d, must be 0", ver)
	case h[3]>>6 != 0:
		return "reserved_bits", fmt.Sprintf("RES0 is %d, must be 0", h[3]>>6)
	case h[5] != 0 || h[6] != 0 || h[7] != 0:
		return "reserved_bits", fmt.Sprintf("RES1 is 0x%02x%02x%02x, must be 0", h[7], h[6], h[5])
	case length < headerLen || (headerLen < length && length <= headerLen+crc32Len):
		return "impossible_length", fmt.Sprintf("LEN %d is impossible (12, or 17 to %d)", length, maxLen)
	}
	return "", ""
}

// crc32Problem says whether a whole frame's CRC-32 is wrong.
func (c Checksums) crc32Problem(raw []byte) (bool, string) {
	n := len(raw) - crc32Len
	stored := uint64(binary.LittleEndian.Uint32(raw[n:]))
	computed := c.crc32.Sum(raw[:n])
	return computed != stored, fmt.Sprintf("CRC-32 is 0x%08x, expected 0x%08x", stored, computed)
}

// Deframer is incremental: Feed any chunks, then Finish. Offsets are
// absolute. It holds at most one maximum-length frame plus the last chunk.
type Deframer struct {
	sums         Checksums
	buf          []byte
	base         int // absolute offset of buf[0]
	garbageStart int
	inGarbage    bool
}

func NewDeframer(sums Checksums) *Deframer {
	return &Deframer{sums: sums}
}

func (d *Deframer) Feed(chunk []byte) []Event {
	d.buf = append(d.buf, chunk...)
	return d.scan(false)
}

func (d *Deframer) Finish() []Event {
	return d.scan(true)
}

func (d *Deframer) drop(n int) {
	d.buf = d.buf[n:]
	d.base += n
}

func (d *Deframer) flushGarbage(out []Event) []Event {
	if d.inGarbage {
		out = append(out, Event{Kind: EvGarbage, Offset: d.garbageStart, Length: d.base - d.garbageStart})
		d.inGarbage = false
	}
	return out
}

func (d *Deframer) scan(final bool) []Event {
	var out []Event
	for len(d.buf) > 0 {
		if d.buf[0] != sof {
			n := bytes.IndexByte(d.buf, sof)
			if n < 0 {
				n = len(d.buf)
			}
			if !d.inGarbage {
				d.garbageStart, d.inGarbage = d.base, true
			}
			d.drop(n)
			continue
		}
		out = d.flushGarbage(out)
		if len(d.buf) < headerLen {
			if !final {
				break
			}
			out = append(out, d.truncated(0))
			continue
		}
		if cls, detail := d.sums.headerProblem(d.buf[:headerLen]); cls != "" {
			out = append(out, Event{Kind: EvRejected, Offset: d.base, Error: cls, Detail: detail, Length: 1})
			d.drop(1)
			continue
		}
		length := frameLength(d.buf)
		if len(d.buf) < length {
			if !final {
				break
			}
			out = append(out, d.truncated(length))
			continue
		}
		raw := append([]byte(nil), d.buf[:length]...)
		if length > headerLen {
			if bad, detail := d.sums.crc32Problem(raw); bad {
				out = append(out, Event{Kind: EvRejected, Offset: d.base, Error: "bad_crc32", Detail: detail, Length: length})
				d.drop(1)
				continue
			}
		}
		out = append(out, Event{Kind: EvFrame, Offset: d.base, Raw: raw})
		d.drop(length)
	}
	if final {
		out = d.flushGarbage(out)
	}
	// Keep the buffer from pinning every byte ever fed.
	if cap(d.buf) > 4*(maxLen+1) && len(d.buf) <= maxLen {
		d.buf = append([]byte(nil), d.buf...)
	}
	return out
}

// truncated reports a frame the input ended inside of, then rescans after
// its start byte like any rejection, so a shorter frame inside it is found.
func (d *Deframer) truncated(length int) Event {
	have := len(d.buf)
	want := "a 12-byte header"
	if length > 0 {
		want = fmt.Sprintf("LEN %d", length)
	}
	ev := Event{Kind: EvRejected, Offset: d.base, Error: "truncated_frame",
		Detail: fmt.Sprintf("input ended after %d byte(s) of %s", have, want), Length: have}
	d.drop(1)
	return ev
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
