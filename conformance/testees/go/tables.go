package main

import (
	"encoding/json"
	"errors"
	"fmt"
	"os"
	"path/filepath"
	"strconv"
)

// Tables is the part of generated/tables/osdk_tables.json this testee
// uses beside the generated library: the value model it answers in and the
// control mode tables.
type Tables struct {
	ControlModes map[string]ControlModeTable  `json:"control_modes"`
	Model        ModelTables                  `json:"model"`
	IfExpr       map[string]map[string]string `json:"if_expressions"`

	// Built after loading.
	typeByClass map[string]string // Go type name (class path joined by "_") -> type key
}

type ModeInfo struct {
	Classification string `json:"classification"`
	Combination    *int   `json:"combination"`
}

// Limit bounds one axis; nil is unbounded.
type Limit struct {
	Min *float64 `json:"min"`
	Max *float64 `json:"max"`
}

type ControlModeTable struct {
	Modes  []ModeInfo                  `json:"modes"`
	Ranges map[string]map[string]Limit `json:"ranges"`
}

type ModelTables struct {
	Types map[string]TypeModel         `json:"types"`
	Enums map[string]map[string]string `json:"enums"`
}

type TypeModel struct {
	ClassPath []string     `json:"class_path"`
	Seq       []string     `json:"seq"`
	Fields    []FieldModel `json:"fields"`
}

type FieldModel struct {
	ID       string `json:"id"`
	Kind     string `json:"kind"`
	Width    int    `json:"width"`
	Enum     string `json:"enum"`
	Optional bool   `json:"optional"`
	Repeat   bool   `json:"repeat"`
}

// tablesPath finds the tables: $OSDK_TABLES, else generated/tables/ in the
// first ancestor of the executable's directory that has it (the binary lives
// in conformance/testees/go/bin of the kit).
func tablesPath() (string, error) {
	if p := os.Getenv("OSDK_TABLES"); p != "" {
		return p, nil
	}
	exe, err := os.Executable()
	if err != nil {
		return "", err
	}
	if resolved, err := filepath.EvalSymlinks(exe); err == nil {
		exe = resolved
	}
	for dir := filepath.Dir(exe); ; dir = filepath.Dir(dir) {
		p := filepath.Join(dir, "generated", "tables", "osdk_tables.json")
		if _, err := os.Stat(p); err == nil {
			return p, nil
		}
		if filepath.Dir(dir) == dir {
			return "", errors.New("generated/tables/osdk_tables.json not found above the executable; set OSDK_TABLES")
		}
	}
}

func loadTables(path string) (*Tables, error) {
	text, err := os.ReadFile(path)
	if err != nil {
		return nil, err
	}
	t := &Tables{}
	if err := json.Unmarshal(text, t); err != nil {
		return nil, fmt.Errorf("%s: %w", path, err)
	}
	if len(t.Model.Types) == 0 || len(t.ControlModes) == 0 {
		return nil, fmt.Errorf("%s: incomplete tables", path)
	}
	t.typeByClass = map[string]string{}
	for key, tm := range t.Model.Types {
		name := ""
		for i, part := range tm.ClassPath {
			if i > 0 {
				name += "_"
			}
			name += part
		}
		t.typeByClass[name] = key
	}
	return t, nil
}

// enumName is the spec's name of an enum value, or nil.
func (t *Tables) enumName(enum string, value int64) any {
	if n, ok := t.Model.Enums[enum][strconv.FormatInt(value, 10)]; ok {
		return n
	}
	return nil
}
