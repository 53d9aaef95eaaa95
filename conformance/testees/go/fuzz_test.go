package main

import (
	"encoding/binary"
	"encoding/hex"
	"encoding/json"
	"errors"
	"fmt"
	"os"
	"path/filepath"
	"strings"
	"sync"
	"testing"

	k "osdk-conformance.local/generated/go/osdk_kaitai"
)

// FuzzDecodeStream: the testee's receiver (Deframer) and stream decoder
// (the generated Kaitai parsers, ACK matching, the value model) on
// arbitrary byte streams, as decode_stream runs them.
//
// The input is read as every stream target reads it (tools/fuzz_corpus.py
// stream_input): the first byte modulo the number of profiles picks the
// profile (in the tables' order), its top six bits plus one the read size;
// the rest is the stream. A finding is a panic
// (streamDecoder.frame is called directly, past the recover that keeps the
// testee alive), an error that is not an *osdk_kaitai.Error, the class undecodable,
// events out of stream order or outside the input, or a frame event that is
// not LEN bytes from a start byte. The message carries the input's hex for
// tools/fuzz_to_vector.py.
//
// Seeds are every decode_stream and decode_frame input of vectors/, so a
// plain `go test` replays them too.
//
//	go test -run '^$' -fuzz '^FuzzDecodeStream$' -fuzztime 60s -parallel 1 .
func FuzzDecodeStream(f *testing.F) {
	te, err := fuzzSetup()
	if err != nil {
		f.Fatal(err)
		// Under ClusterFuzzLite (go-118-fuzz-build) F.Fatal returns; a
		// testee without tables must not pass as "nothing found".
		panic(err)
	}
	for _, seed := range vectorSeeds(k.Profiles) {
		f.Add(seed)
	}
	f.Fuzz(func(t *testing.T, data []byte) {
		if problem := checkStream(te, data); problem != "" {
			t.Fatalf("%s\ninput %s", problem, hex.EncodeToString(data))
		}
	})
}

var (
	fuzzOnce   sync.Once
	fuzzTestee *Testee
	fuzzErr    error
	seedOnce   sync.Once
	seeds      [][]byte
)

// fuzzSetup loads the tables once: go-118-fuzz-build calls the Fuzz
// function again for every input.
func fuzzSetup() (*Testee, error) {
	fuzzOnce.Do(func() {
		path, err := fuzzTablesPath()
		if err == nil {
			var tb *Tables
			if tb, err = loadTables(path); err == nil {
				fuzzTestee, err = NewTestee(tb)
			}
		}
		fuzzErr = err
	})
	return fuzzTestee, fuzzErr
}

// fuzzTablesPath: $OSDK_TABLES, generated/tables above the working
// directory (go test runs in the package), else above the executable (a
// ClusterFuzzLite build copies the tables beside the fuzzer).
func fuzzTablesPath() (string, error) {
	if p := os.Getenv("OSDK_TABLES"); p != "" {
		return p, nil
	}
	if p := aboveWorkingDir(filepath.Join("generated", "tables", "osdk_tables.json")); p != "" {
		return p, nil
	}
	return tablesPath()
}

func aboveWorkingDir(rel string) string {
	dir, err := os.Getwd()
	if err != nil {
		return ""
	}
	for {
		if p := filepath.Join(dir, rel); fileExists(p) {
			return p
		}
		if filepath.Dir(dir) == dir {
			return ""
		}
		dir = filepath.Dir(dir)
	}
}

func fileExists(p string) bool {
	_, err := os.Stat(p)
	return err == nil
}

// vectorSeeds are the stream inputs tools/fuzz_corpus.py writes for the
// deframer target, read from vectors/ once (none outside a checkout).
func vectorSeeds(profiles []string) [][]byte {
	seedOnce.Do(func() {
		dir := aboveWorkingDir(filepath.Join("vectors", "MANIFEST.json"))
		if dir == "" {
			return
		}
		for _, name := range []string{"frames.json", "streams.json"} {
			text, err := os.ReadFile(filepath.Join(filepath.Dir(dir), name))
			if err != nil {
				continue
			}
			var doc struct {
				TestGroups []struct {
					Operation string `json:"operation"`
					Profile   string `json:"profile"`
					Tests     []struct {
						Input struct {
							Hex string `json:"hex"`
						} `json:"input"`
					} `json:"tests"`
				} `json:"testGroups"`
			}
			if json.Unmarshal(text, &doc) != nil {
				continue
			}
			for _, g := range doc.TestGroups {
				for _, c := range g.Tests {
					raw, err := hex.DecodeString(c.Input.Hex)
					if err == nil {
						seeds = append(seeds, streamSeed(profiles, g.Profile, raw))
					}
				}
			}
		}
	})
	return seeds
}

// streamSeed is tools/fuzz_corpus.py stream_seed; the selector byte counts
// profiles in the tables' order.
func streamSeed(profiles []string, profile string, stream []byte) []byte {
	want := 0
	for i, p := range profiles {
		if p == profile {
			want = i
		}
	}
	high := (len(stream) % 64) << 2
	sel := high
	for low := 0; low < 4; low++ {
		if (high|low)%3 == want {
			sel = high | low
			break
		}
	}
	return append([]byte{byte(sel)}, stream...)
}

func checkStream(te *Testee, data []byte) string {
	if len(data) == 0 {
		return ""
	}
	profiles := k.Profiles
	profile := profiles[int(data[0])%len(profiles)]
	size := int(data[0]>>2) + 1
	stream := data[1:]
	var sizes []int
	for n := len(stream) / size; n > 0; n-- {
		sizes = append(sizes, size)
	}
	dec := &streamDecoder{t: te, profile: profile, models: true}
	d := k.NewDeframer()
	next := 0
	check := func(evs []k.Event) string {
		for _, ev := range evs {
			length := ev.Length
			if ev.Offset < next || length < 1 || ev.Offset+length > len(stream) {
				return fmt.Sprintf("event %+v out of order or outside the %d-byte stream", ev, len(stream))
			}
			next = ev.Offset + 1 // a rejected start byte lets the scan resume at the next byte
			switch ev.Kind {
			case k.EventGarbage:
				next = ev.Offset + ev.Length
			case k.EventError:
				if ev.Err == nil || ev.Err.Class == "undecodable" || ev.Err.Class == "" {
					return fmt.Sprintf("receiver rejection without a class: %+v", ev.Err)
				}
			case k.EventFrame:
				if len(ev.Raw) != ev.Length || ev.Raw[0] != 0xAA || int(binary.LittleEndian.Uint16(ev.Raw[1:3])&0x3FF) != len(ev.Raw) {
					return fmt.Sprintf("frame event at %d is not one whole frame", ev.Offset)
				}
				if problem := checkFrame(dec, ev); problem != "" {
					return problem
				}
			}
		}
		return ""
	}
	for _, chunk := range splitChunks(stream, sizes) {
		if problem := check(d.Feed(chunk)); problem != "" {
			return problem
		}
	}
	return check(d.Finish())
}

// checkFrame decodes one frame event as decode_stream does, minus its recover.
func checkFrame(dec *streamDecoder, ev k.Event) string {
	out, err := dec.frame(ev)
	if err != nil {
		var rej *k.Error
		if !errors.As(err, &rej) {
			return fmt.Sprintf("frame at %d: internal error (not a *osdk_kaitai.Error): %v", ev.Offset, err)
		}
		out = dec.errorEvent(ev, rej, nil)
	}
	if cls, _ := out.Get("error"); cls == "undecodable" {
		detail, _ := out.Get("detail")
		return fmt.Sprintf("frame at %d: undecodable: %v", ev.Offset, detail)
	}
	var b strings.Builder
	writeJSON(&b, out)
	if !json.Valid([]byte(b.String())) {
		return fmt.Sprintf("frame at %d: the event is not valid JSON: %s", ev.Offset, b.String())
	}
	return ""
}
