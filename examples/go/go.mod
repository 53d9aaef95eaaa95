module osdk-conformance.local/examples/go

go 1.23.0

require osdk-conformance.local/generated/go v0.0.0

require (
	github.com/kaitai-io/kaitai_struct_go_runtime v0.11.0 // indirect
	golang.org/x/text v0.28.0 // indirect
)

replace osdk-conformance.local/generated/go => ../../generated/go
