package main

import (
	"fmt"
	"math"
	"reflect"
)

// The JSON value model (docs/VALUE-MODEL.md) of a generated Go object,
// driven by the tables' model of its ksy type: which fields to show, in
// wire order, and what each is (float width, enum, bool, bytes, ...).
// Go float32/float64 fields hold the wire's exact bits (no NaN is quieted),
// so floats need no recovery from the input.

type Modeler struct {
	t *Tables
}

// typeKey is the ksy type key of a generated struct type.
func (m Modeler) typeKey(t reflect.Type) (string, error) {
	if key, ok := m.t.typeByClass[t.Name()]; ok {
		return key, nil
	}
	return "", fmt.Errorf("no ksy type for the Go type %s", t.Name())
}

// Object is the model of a pointer to a generated struct.
func (m Modeler) Object(ptr any) (Obj, error) {
	return m.object(reflect.ValueOf(ptr))
}

func (m Modeler) object(ptr reflect.Value) (Obj, error) {
	if ptr.Kind() != reflect.Pointer || ptr.IsNil() || ptr.Elem().Kind() != reflect.Struct {
		return nil, fmt.Errorf("model of a %s, not of a parsed structure", ptr.Kind())
	}
	key, err := m.typeKey(ptr.Elem().Type())
	if err != nil {
		return nil, err
	}
	s := ptr.Elem()
	out := Obj{}
	for _, f := range m.t.Model.Types[key].Fields {
		if f.Optional {
			expr, ok := m.t.IfExpr[key][f.ID]
			if !ok {
				return nil, fmt.Errorf("%s.%s: no if expression in the tables", key, f.ID)
			}
			present, err := evalCondition(expr, ptr)
			if err != nil {
				return nil, fmt.Errorf("%s.%s: %w", key, f.ID, err)
			}
			if !present {
				continue
			}
		}
		fv := s.FieldByName(camel(f.ID))
		if !fv.IsValid() {
			return nil, fmt.Errorf("%s: the Go type %s has no field %s", key, s.Type().Name(), camel(f.ID))
		}
		var v any
		if f.Kind == "switch" && isNilValue(fv) {
			// A switch whose matching case is raw bytes (AES frame data): the
			// Go target keeps those only in _raw_<Field>.
			raw := s.FieldByName("_raw_" + camel(f.ID))
			if !raw.IsValid() || raw.Kind() != reflect.Slice || raw.IsNil() {
				return nil, fmt.Errorf("%s.%s: present but empty", key, f.ID)
			}
			v = hexString(raw.Bytes())
		} else if f.Repeat {
			if fv.Kind() != reflect.Slice {
				return nil, fmt.Errorf("%s.%s: repeat field is a %s", key, f.ID, fv.Kind())
			}
			items := make([]any, fv.Len())
			for i := range items {
				if items[i], err = m.value(fv.Index(i), f, key); err != nil {
					return nil, err
				}
			}
			v = items
		} else if v, err = m.value(fv, f, key); err != nil {
			return nil, err
		}
		out = append(out, KV{f.ID, v})
	}
	return out, nil
}

func isNilValue(v reflect.Value) bool {
	switch v.Kind() {
	case reflect.Pointer, reflect.Interface, reflect.Slice, reflect.Map:
		return v.IsNil()
	}
	return false
}

func (m Modeler) value(v reflect.Value, f FieldModel, key string) (any, error) {
	where := key + "." + f.ID
	switch f.Kind {
	case "struct", "switch":
		for v.Kind() == reflect.Interface {
			if v.IsNil() {
				return nil, fmt.Errorf("%s: nil value", where)
			}
			v = v.Elem()
		}
		if v.Kind() == reflect.Slice && v.Type().Elem().Kind() == reflect.Uint8 {
			return hexString(v.Bytes()), nil
		}
		return m.object(v)
	case "bytes":
		if v.Kind() != reflect.Slice || v.Type().Elem().Kind() != reflect.Uint8 {
			return nil, fmt.Errorf("%s: bytes field is a %s", where, v.Type())
		}
		return hexString(v.Bytes()), nil
	case "bool":
		if v.Kind() != reflect.Bool {
			return nil, fmt.Errorf("%s: bool field is a %s", where, v.Type())
		}
		return v.Bool(), nil
	case "float":
		switch {
		case f.Width == 4 && v.Kind() == reflect.Float32 && v.CanInterface():
			// Not v.Float(): widening to float64 and back quiets a signalling NaN.
			if x, ok := v.Interface().(float32); ok {
				return float32Model(math.Float32bits(x)), nil
			}
		case f.Width == 8 && v.Kind() == reflect.Float64:
			return float64Model(math.Float64bits(v.Float())), nil
		}
		return nil, fmt.Errorf("%s: f%d field is a %s", where, f.Width, v.Type())
	case "int", "bits":
		var n any
		var signed int64
		switch v.Kind() {
		case reflect.Int, reflect.Int8, reflect.Int16, reflect.Int32, reflect.Int64:
			signed = v.Int()
			n = signed
		case reflect.Uint, reflect.Uint8, reflect.Uint16, reflect.Uint32, reflect.Uint64:
			n = v.Uint()
			signed = int64(v.Uint())
		case reflect.Bool: // a b1 with an enum is still read as a bit
			if v.Bool() {
				signed = 1
			}
			n = signed
		default:
			return nil, fmt.Errorf("%s: integer field is a %s", where, v.Type())
		}
		if f.Enum != "" {
			return Obj{{"value", n}, {"name", m.t.enumName(f.Enum, signed)}}, nil
		}
		return n, nil
	}
	return nil, fmt.Errorf("%s: unknown field kind %q", where, f.Kind)
}
