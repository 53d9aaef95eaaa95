package main

// The bench mode (conformance/PROTOCOL.md): `osdk-go-testee --bench FILE
// --profile P` runs FILE (standard input for `-`) in reads of at most 64 KiB
// through decode_stream's own loop (eventStream) without value models, keeps
// only counters, and prints one JSON line with the counts and the seconds of
// the loop. Bad arguments or unreadable input: one stderr line, exit 2.

import (
	"errors"
	"fmt"
	"io"
	"os"
	"strconv"
	"strings"
	"time"

	k "osdk-conformance.local/generated/go/osdk_kaitai"
)

const (
	benchReadSize = 64 * 1024
	benchUsage    = "usage: --bench FILE|- --profile P"
)

// parseBenchArgs reads `--bench FILE --profile P`, in either order.
func parseBenchArgs(args []string, profiles []string) (path, profile string, err error) {
	opts := map[string]string{}
	for i := 0; i < len(args); i += 2 {
		key := args[i]
		if key != "--bench" && key != "--profile" {
			return "", "", fmt.Errorf("unknown argument %q; %s", key, benchUsage)
		}
		if i+1 >= len(args) {
			return "", "", fmt.Errorf("%s needs a value; %s", key, benchUsage)
		}
		if _, twice := opts[key]; twice {
			return "", "", fmt.Errorf("%s given twice; %s", key, benchUsage)
		}
		opts[key] = args[i+1]
	}
	path, hasPath := opts["--bench"]
	profile, hasProfile := opts["--profile"]
	if !hasPath || !hasProfile {
		return "", "", errors.New(benchUsage)
	}
	for _, p := range profiles {
		if p == profile {
			return path, profile, nil
		}
	}
	return "", "", fmt.Errorf("unknown profile %q (known: %s)", profile, strings.Join(profiles, ", "))
}

// bench decodes the file and returns the result line's fields after "impl".
func (t *Testee) bench(path, profile string) (Obj, error) {
	in := os.Stdin
	if path != "-" {
		f, err := os.Open(path)
		if err != nil {
			return nil, fmt.Errorf("cannot read %s: %v", path, reason(err))
		}
		defer f.Close()
		in = f
	}
	var frames, errs, garbage, total int64
	stream := t.newEventStream(profile, false, func(ev Obj) {
		switch kind, _ := ev.Get("kind"); kind {
		case "frame":
			frames++
		case "error":
			errs++
		default:
			n, _ := ev.Get("length")
			garbage += int64(n.(int))
		}
	})
	// The deframer copies what it keeps, so one read buffer serves every read.
	buf := make([]byte, benchReadSize)
	start := time.Now() // carries a monotonic reading; time.Since uses it
	for {
		n, err := in.Read(buf)
		total += int64(n)
		stream.Feed(buf[:n])
		if errors.Is(err, io.EOF) {
			break
		}
		if err != nil {
			return nil, fmt.Errorf("cannot read %s: %v", path, reason(err))
		}
	}
	stream.Finish()
	seconds := time.Since(start).Seconds()
	return Obj{{"profile", profile}, {"bytes", total}, {"frames", frames}, {"errors", errs},
		{"garbage_bytes", garbage}, {"seconds", Number(strconv.FormatFloat(seconds, 'f', 6, 64))}}, nil
}

// runBench is the bench mode's main; it returns the exit status.
func runBench(args []string) int {
	fail := func(err error) int {
		fmt.Fprintln(os.Stderr, "go --bench:", err)
		return 2
	}
	t, err := setup()
	if err != nil {
		return fail(err)
	}
	path, profile, err := parseBenchArgs(args, k.Profiles)
	if err != nil {
		return fail(err)
	}
	result, err := t.bench(path, profile)
	if err != nil {
		return fail(err)
	}
	var b strings.Builder
	writeJSON(&b, append(Obj{{"impl", "go"}}, result...))
	fmt.Println(b.String())
	return 0
}

// reason drops the operation and path an *os.PathError repeats.
func reason(err error) error {
	if inner := errors.Unwrap(err); inner != nil {
		return inner
	}
	return err
}
