# Two entry points (see README.md):
#   make kit   set up, then run the conformance kit
#   make test  set up, then run the whole test suite
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
PY_OK  := $(VENV)/.installed
ACCEL_OK  := $(VENV)/.accel-built
ACCEL_SRC := osdk_conformance/reference/_accel.c $(wildcard generated/c/*.[ch] generated/cpython/*.[ch])
JS_OK  := tools/ksc/node_modules/.installed

# Python's bytecode caches (__pycache__/, ignored by git) stay on for every
# recipe: with PYTHONDONTWRITEBYTECODE set in the caller's environment each
# of the thousands of Python processes the suite and the kit start compiles
# every module it imports from source again.
unexport PYTHONDONTWRITEBYTECODE

.PHONY: setup system-packages testees examples kit test quick properties memory prove regen check-generated vectors bench fuzz clean

# Bundled testees in other languages, each built by its own Makefile with
# the language's standard tool (npm, Maven, go build, cc).
LANGS  := javascript java go c

setup: system-packages $(PY_OK) $(ACCEL_OK) $(JS_OK) testees examples

# clang + sanitizer/libFuzzer runtimes, tshark and Chromium (the report pages), from Debian, pinned (tools/apt-packages.sh).
system-packages:
	@sh tools/apt-packages.sh

testees: $(PY_OK) $(JS_OK)
	@for lang in $(LANGS); do $(MAKE) --no-print-directory -C conformance/testees/$$lang build || exit 1; done
	@$(MAKE) --no-print-directory -C conformance/testees/c-target boards
	@$(MAKE) --no-print-directory -C conformance/baseline build

# The generated libraries' examples (examples/<language>/), each built the
# way a user of that language builds against the packaged library; the tests
# run them (generated/README.md).
EXAMPLES := python $(LANGS)
examples: $(PY_OK) testees
	@for lang in $(EXAMPLES); do $(MAKE) --no-print-directory -C examples/$$lang build || exit 1; done

$(PY_OK): pyproject.toml constraints.txt
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install --quiet --no-compile --disable-pip-version-check -c constraints.txt -e '.[test,flight]'
	touch $@

# The native accelerator (osdk_conformance/reference/_accel.c and the generated
# C it compiles), built by the editable install: rebuilt when a source
# changes, and a failed build is an error here (this README asks for gcc),
# not the silent fallback to pure Python that a user's pip install allows.
$(ACCEL_OK): $(PY_OK) $(ACCEL_SRC)
	$(BIN)/pip install --quiet --disable-pip-version-check -c constraints.txt --no-deps -e .
	$(BIN)/python -c "import osdk_conformance.reference._accel"
	touch $@

$(JS_OK): tools/ksc/package.json tools/ksc/package-lock.json
	cd tools/ksc && npm ci --no-audit --no-fund --loglevel=error
	touch $@

regen: setup
	$(BIN)/python tools/regen.py
	$(BIN)/python tools/gen_schemas.py

check-generated: setup
	$(BIN)/python tools/regen.py --check
	$(BIN)/python tools/gen_schemas.py --check

# Regenerate the golden vectors (vectors/*.json, MANIFEST.json) from the spec.
vectors: setup
	$(BIN)/python tools/gen_vectors.py

kit: setup
	$(BIN)/osdkc kit

# The whole suite; hypothesis runs its CI profile (tests/conftest.py).
# tools/run_tests.py runs two pytest runs side by side: the `realtime` tests,
# which judge a live simulator's timing and mostly wait, one at a time at
# normal priority; everything else at nice 10, pytest-xdist spreading the test
# files over the cores (a file's tests stay together, so its module fixtures
# run once). The realtime part's output is printed at the end.
# tests/test_vectors.py checks that vectors/ regenerates byte for byte.
JOBS ?= auto
test: setup check-generated
	$(BIN)/python tools/run_tests.py --jobs $(JOBS)

# A fast subset for development: no test marked slow, few examples, the
# realtime tests two at a time.
quick: setup
	OSDK_HYPOTHESIS_PROFILE=dev $(BIN)/python tools/run_tests.py --jobs $(JOBS) --realtime-jobs 2 --marks 'not slow'

# The long property campaign: every hypothesis property of the suite with
# 10,000 randomized examples each (the suite's own smoke run is 100, fixed), the
# Kaitai-vs-Construct differential test above all. About an hour on 2 cores.
PROPERTY_TESTS := tests/test_kaitai_vs_construct.py tests/test_crc.py tests/test_construct_spec.py \
                  tests/test_deframe.py tests/test_stream_properties.py tests/test_construct_compiled.py
properties: setup
	OSDK_HYPOTHESIS_PROFILE=campaign $(BIN)/pytest -q -n $(JOBS) --dist loadfile $(PROPERTY_TESTS)

# The memory campaign: every implementation's peak RSS on every hostile stream,
# short against long, and a gibibyte through each (tests/test_bounded_memory.py;
# the suite runs a smoke subset of it). About 3 minutes on 2 cores.
memory: setup
	OSDK_MEMORY_CAMPAIGN=1 $(BIN)/pytest -q -n $(JOBS) tests/test_bounded_memory.py

# The proof (docs/VERIFICATION.md): Frama-C WP proves the units of the
# generated C library that carry contracts free of runtime errors (prover
# answers cached per goal in .cache/prove/), then checks that each planted
# bounds bug fails the proof. Fails on any unproved goal or uncaught bug.
prove: setup
	$(BIN)/python tools/prove.py --mutants

# Benchmarks (docs/PERFORMANCE.md): every section, the full corpora; rewrites
# the results block of docs/PERFORMANCE.md. Takes tens of minutes.
bench: setup
	@mkdir -p reports
	mkdir -p reports && $(BIN)/osdkc bench --markdown docs/PERFORMANCE.md --json > reports/bench.json

# Every coverage-guided fuzz target for FUZZ_SECONDS each, seeded from
# vectors/ (docs/FUZZING.md): C libFuzzer (deframer, broadcast), Python
# atheris, Go native fuzzing. A finding stops with a non-zero exit; its input
# is in conformance/testees/c/build/findings/, fuzz/build/findings/ or
# conformance/testees/go/testdata/fuzz/ (tools/fuzz_to_vector.py makes it a vector).
FUZZ_SECONDS ?= 60
fuzz: setup
	$(MAKE) --no-print-directory -C conformance/testees/c fuzz-smoke FUZZ_SECONDS=$(FUZZ_SECONDS)
	@mkdir -p fuzz/build/corpus fuzz/build/findings
	$(BIN)/python tools/fuzz_corpus.py deframer fuzz/build/corpus
	$(BIN)/python fuzz/fuzz_decode.py fuzz/build/corpus -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 \
	  -artifact_prefix=fuzz/build/findings/
	cd conformance/testees/go && go test -run '^$$' -fuzz '^FuzzDecodeStream$$' -fuzztime $(FUZZ_SECONDS)s \
	  -fuzzminimizetime 100x -parallel 1 .

clean:
	rm -rf $(VENV) tools/ksc/node_modules .pytest_cache .hypothesis .cache
	@for lang in $(LANGS); do $(MAKE) --no-print-directory -C conformance/testees/$$lang clean; done
	@for lang in $(EXAMPLES); do $(MAKE) --no-print-directory -C examples/$$lang clean; done
	@$(MAKE) --no-print-directory -C conformance/baseline clean
