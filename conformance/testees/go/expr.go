package main

import (
	"fmt"
	"reflect"
	"strconv"
	"strings"
	"unicode"
)

// A Go object cannot show that an integer field was skipped by its `if`
// (it keeps a zero there), so the model evaluates the field's `if`
// expression from the tables against the parsed object. The grammar is the
// part of the Kaitai expression language such conditions use: `or`, `and`,
// `not`, comparisons, parentheses, integer and boolean literals, and names
// with `_parent.` / `_root.` paths. Anything else is an error, never a guess.

type exprParser struct {
	toks []string
	pos  int
	obj  reflect.Value // pointer to the struct the expression belongs to
}

func evalCondition(expr string, obj reflect.Value) (bool, error) {
	toks, err := tokenize(expr)
	if err != nil {
		return false, err
	}
	p := &exprParser{toks: toks, obj: obj}
	v, err := p.or()
	if err != nil {
		return false, fmt.Errorf("if %q: %w", expr, err)
	}
	if p.pos != len(p.toks) {
		return false, fmt.Errorf("if %q: unexpected %q", expr, p.toks[p.pos])
	}
	b, ok := v.(bool)
	if !ok {
		return false, fmt.Errorf("if %q: not a boolean", expr)
	}
	return b, nil
}

func tokenize(s string) ([]string, error) {
	var toks []string
	for i := 0; i < len(s); {
		c := rune(s[i])
		switch {
		case c == ' ' || c == '\t':
			i++
		case c == '(' || c == ')':
			toks = append(toks, string(c))
			i++
		case strings.ContainsRune("<>=!", c):
			if i+1 < len(s) && s[i+1] == '=' {
				toks = append(toks, s[i:i+2])
				i += 2
			} else if c == '<' || c == '>' {
				toks = append(toks, string(c))
				i++
			} else {
				return nil, fmt.Errorf("if %q: bad operator at %d", s, i)
			}
		case c == '_' || c == '.' || unicode.IsLetter(c) || unicode.IsDigit(c):
			j := i
			for j < len(s) && (s[j] == '_' || s[j] == '.' || unicode.IsLetter(rune(s[j])) || unicode.IsDigit(rune(s[j]))) {
				j++
			}
			toks = append(toks, s[i:j])
			i = j
		default:
			return nil, fmt.Errorf("if %q: unsupported character %q", s, c)
		}
	}
	return toks, nil
}

func (p *exprParser) peek() string {
	if p.pos < len(p.toks) {
		return p.toks[p.pos]
	}
	return ""
}

func (p *exprParser) or() (any, error) {
	left, err := p.and()
	for err == nil && p.peek() == "or" {
		p.pos++
		var right any
		if right, err = p.and(); err == nil {
			left, err = boolOp(left, right, func(a, b bool) bool { return a || b })
		}
	}
	return left, err
}

func (p *exprParser) and() (any, error) {
	left, err := p.not()
	for err == nil && p.peek() == "and" {
		p.pos++
		var right any
		if right, err = p.not(); err == nil {
			left, err = boolOp(left, right, func(a, b bool) bool { return a && b })
		}
	}
	return left, err
}

func boolOp(a, b any, op func(a, b bool) bool) (any, error) {
	x, ok1 := a.(bool)
	y, ok2 := b.(bool)
	if !ok1 || !ok2 {
		return nil, fmt.Errorf("and/or of non-booleans")
	}
	return op(x, y), nil
}

func (p *exprParser) not() (any, error) {
	if p.peek() == "not" {
		p.pos++
		v, err := p.not()
		if err != nil {
			return nil, err
		}
		b, ok := v.(bool)
		if !ok {
			return nil, fmt.Errorf("not of a non-boolean")
		}
		return !b, nil
	}
	return p.comparison()
}

func (p *exprParser) comparison() (any, error) {
	left, err := p.primary()
	if err != nil {
		return nil, err
	}
	op := p.peek()
	switch op {
	case "==", "!=", "<", "<=", ">", ">=":
	default:
		return left, nil
	}
	p.pos++
	right, err := p.primary()
	if err != nil {
		return nil, err
	}
	if lb, ok := left.(bool); ok {
		rb, ok := right.(bool)
		if !ok || (op != "==" && op != "!=") {
			return nil, fmt.Errorf("bad comparison of booleans")
		}
		return (lb == rb) == (op == "=="), nil
	}
	a, ok1 := left.(int64)
	b, ok2 := right.(int64)
	if !ok1 || !ok2 {
		return nil, fmt.Errorf("comparison of non-integers")
	}
	return map[string]bool{"==": a == b, "!=": a != b, "<": a < b, "<=": a <= b, ">": a > b, ">=": a >= b}[op], nil
}

func (p *exprParser) primary() (any, error) {
	tok := p.peek()
	if tok == "" {
		return nil, fmt.Errorf("unexpected end")
	}
	p.pos++
	switch {
	case tok == "(":
		v, err := p.or()
		if err != nil {
			return nil, err
		}
		if p.peek() != ")" {
			return nil, fmt.Errorf("missing )")
		}
		p.pos++
		return v, nil
	case tok == "true" || tok == "false":
		return tok == "true", nil
	case tok[0] >= '0' && tok[0] <= '9':
		n, err := strconv.ParseInt(strings.ReplaceAll(tok, "_", ""), 0, 64)
		if err != nil {
			return nil, fmt.Errorf("bad number %q", tok)
		}
		return n, nil
	}
	return resolve(p.obj, tok)
}

// resolve reads a (dotted) name on a parsed object: a seq field or param is
// an exported field; _parent and _root are the object's own links (read
// through reflection, read-only).
func resolve(obj reflect.Value, path string) (any, error) {
	v := obj
	for _, name := range strings.Split(path, ".") {
		for v.Kind() == reflect.Pointer || v.Kind() == reflect.Interface {
			if v.IsNil() {
				return nil, fmt.Errorf("%s: nil on the way", path)
			}
			v = v.Elem()
		}
		if v.Kind() != reflect.Struct {
			return nil, fmt.Errorf("%s: not a structure", path)
		}
		goName := name
		if name != "_parent" && name != "_root" {
			goName = camel(name)
		}
		f := v.FieldByName(goName)
		if !f.IsValid() {
			inst, err := instance(v, goName)
			if err != nil {
				return nil, fmt.Errorf("%s: %w", path, err)
			}
			f = inst
		}
		v = f
	}
	switch v.Kind() {
	case reflect.Bool:
		return v.Bool(), nil
	case reflect.Int, reflect.Int8, reflect.Int16, reflect.Int32, reflect.Int64:
		return v.Int(), nil
	case reflect.Uint, reflect.Uint8, reflect.Uint16, reflect.Uint32, reflect.Uint64:
		u := v.Uint()
		if u > 1<<62 {
			return nil, fmt.Errorf("%s: integer too large", path)
		}
		return int64(u), nil
	}
	return nil, fmt.Errorf("%s: unsupported value kind %s", path, v.Kind())
}

// instance computes a value instance (a ksy `instances` entry) with the
// method the Kaitai compiler generated for it, so its expression is never
// evaluated a second way here.
func instance(v reflect.Value, goName string) (reflect.Value, error) {
	if !v.CanAddr() {
		return reflect.Value{}, fmt.Errorf("no field %s in %s", goName, v.Type().Name())
	}
	m := v.Addr().MethodByName(goName)
	if !m.IsValid() || m.Type().NumIn() != 0 || m.Type().NumOut() != 2 {
		return reflect.Value{}, fmt.Errorf("no field or instance %s in %s", goName, v.Type().Name())
	}
	out := m.Call(nil)
	if err, _ := out[1].Interface().(error); err != nil {
		return reflect.Value{}, fmt.Errorf("instance %s: %w", goName, err)
	}
	return out[0], nil
}

// camel is the Go name the Kaitai compiler gives a ksy id (has_ns_and_sync
// -> HasNsAndSync, crc16 -> Crc16).
func camel(id string) string {
	var b strings.Builder
	for _, part := range strings.Split(id, "_") {
		if part == "" {
			continue
		}
		b.WriteString(strings.ToUpper(part[:1]) + part[1:])
	}
	return b.String()
}
