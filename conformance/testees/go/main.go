// Command osdk-go-testee is the bundled "go" testee of the conformance kit:
// the Kaitai-generated Go parsers (generated/go/osdk_kaitai) behind the
// JSON Lines protocol of conformance/PROTOCOL.md. A port of the glue of
// conformance/testees/kaitai_python_testee.py; see README.md.
package main

import (
	"bufio"
	"encoding/json"
	"errors"
	"fmt"
	"io"
	"os"
	"strings"
)

type jsonNumber = json.Number

func main() {
	if len(os.Args) > 1 { // --bench FILE --profile P (bench.go)
		os.Exit(runBench(os.Args[1:]))
	}
	testee, loadErr := setup()
	if loadErr != nil {
		fmt.Fprintln(os.Stderr, "osdk-go-testee:", loadErr)
	}
	in := bufio.NewReader(os.Stdin)
	out := bufio.NewWriter(os.Stdout)
	for {
		line, err := in.ReadString('\n')
		if strings.TrimSpace(line) != "" {
			var text string
			if loadErr != nil {
				text = failure("internal_error", loadErr.Error())
			} else {
				text = respond(testee, line)
			}
			out.WriteString(text + "\n")
			out.Flush()
		}
		if err != nil {
			if !errors.Is(err, io.EOF) {
				fmt.Fprintln(os.Stderr, "osdk-go-testee: reading stdin:", err)
				os.Exit(1)
			}
			return
		}
	}
}

func setup() (*Testee, error) {
	path, err := tablesPath()
	if err != nil {
		return nil, err
	}
	tb, err := loadTables(path)
	if err != nil {
		return nil, err
	}
	return NewTestee(tb)
}

// respond answers one request line: never a dead testee, whatever the line
// holds. Input it cannot use is bad_request, a bug of its own internal_error.
func respond(t *Testee, line string) (text string) {
	defer func() {
		if p := recover(); p != nil {
			text = failure("internal_error", fmt.Sprintf("panic: %v", p))
		}
	}()
	dec := json.NewDecoder(strings.NewReader(line))
	dec.UseNumber()
	var v any
	if err := dec.Decode(&v); err != nil {
		return failure("bad_request", "JSON: "+err.Error())
	}
	if dec.More() {
		return failure("bad_request", "JSON: more than one value on the line")
	}
	req, ok := v.(map[string]any)
	if !ok {
		return failure("bad_request", `a request is a JSON object with an "op" string`)
	}
	res, err := t.answer(request(req))
	if err != nil {
		var bad badRequest
		if errors.As(err, &bad) {
			return failure("bad_request", bad.Error())
		}
		return failure("internal_error", err.Error())
	}
	var b strings.Builder
	writeJSON(&b, res)
	return b.String()
}

func failure(class, detail string) string {
	var b strings.Builder
	writeJSON(&b, Obj{{"ok", false}, {"error", class}, {"detail", detail}})
	return b.String()
}
