package main

import (
	"errors"
	"fmt"
	"io"
	"reflect"
	"regexp"
	"slices"
	"sort"
	"strconv"
	"strings"

	"github.com/kaitai-io/kaitai_struct_go_runtime/kaitai"

	k "osdk-conformance.local/generated/go/osdk_kaitai"
)

// Rejection is an input rejected with an error class of docs/VALUE-MODEL.md.
type Rejection struct {
	Class, Detail string
}

func (r *Rejection) Error() string { return r.Class + ": " + r.Detail }

func reject(class, format string, args ...any) *Rejection {
	return &Rejection{class, fmt.Sprintf(format, args...)}
}

var seqPath = regexp.MustCompile(`^/seq/(\d+)$`)

// rejection turns an error of a generated Read into an error class.
//
// A failed `valid` names its field only by position ("/seq/N") in the type
// whose Read raised it, and Go errors do not say which type that was (the
// failing object is not even attached to its parent). The raising type is
// found from what the error does carry: the candidates are the generated
// types whose seq field N has a check (tables: checked_fields) and whose Go
// field has exactly the type of the error's Actual() value (the field is
// what the check reports). All candidates must agree on the class, else the
// answer is undecodable.
func (tb *Tables) rejection(err error) *Rejection {
	var vf kaitai.ValidationFailedError
	if errors.As(err, &vf) {
		fields, class := tb.raisingFields(vf)
		if class == "" {
			return reject("undecodable", "%s (raising field unknown): %s", vf.SrcPath(), oneLine(err))
		}
		return reject(class, "%s: %s", strings.Join(fields, " or "), oneLine(err))
	}
	var eos kaitai.EndOfStreamError
	if errors.Is(err, io.EOF) || errors.Is(err, io.ErrUnexpectedEOF) || errors.As(err, &eos) {
		return reject("truncated_payload", "%s", oneLine(err))
	}
	return reject("undecodable", "%T: %s", err, oneLine(err))
}

func (tb *Tables) raisingFields(vf kaitai.ValidationFailedError) ([]string, string) {
	m := seqPath.FindStringSubmatch(vf.SrcPath())
	if m == nil || vf.Actual() == nil {
		return nil, ""
	}
	n, _ := strconv.Atoi(m[1])
	actual := reflect.TypeOf(vf.Actual())
	var fields []string
	classes := map[string]bool{}
	for _, t := range k.Types {
		key, ok := tb.typeByClass[t.Name()]
		if !ok || n >= len(tb.Model.Types[key].Seq) {
			continue
		}
		id := tb.Model.Types[key].Seq[n]
		if !slices.Contains(tb.Checked[key], id) {
			continue
		}
		if f, ok := t.FieldByName(camel(id)); !ok || f.Type != actual {
			continue
		}
		class, ok := tb.ErrorByField[id]
		if !ok {
			class = "undecodable"
		}
		fields = append(fields, key+"."+id)
		classes[class] = true
	}
	if len(classes) != 1 {
		return nil, ""
	}
	sort.Strings(fields)
	for c := range classes {
		return fields, c
	}
	return nil, ""
}

func oneLine(err error) string {
	return strings.Join(strings.Fields(err.Error()), " ")
}
