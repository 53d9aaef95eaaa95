"""Protocol primitives every other layer stands on: the rules (spec/rules.yaml),
the frame checksums and deframer, command names, the JSON value model, the
pcapng capture format, frames on the wire, errors, checked CLI option types
and where the repository keeps things. Imports nothing else of the package."""
