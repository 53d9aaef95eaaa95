"""The conformance harness: golden vectors, testee supervision, the runner,
reports, the mutation self-check, differential fuzzing and the request loop
the bundled Python testees serve."""
