# The two commands of the README: `make` (generate every shipped equation in every language into
# build/, with a summary, and the variant report in build/report/) and `make test`. Both install
# what is missing first (scripts/setup), Python packages into the checkout's own .venv: every
# command below, and every test's subprocess, runs this checkout's code and nobody else's.
PYTHON := $(CURDIR)/.venv/bin/python

.PHONY: all build test setup clean distclean bench fuzz

all: build

setup:
	./scripts/setup

build: setup
	$(PYTHON) -m max2code build -o build equations/*.mxm
	$(PYTHON) -m max2code report -o build/report equations/*.mxm > /dev/null
	@echo "variant report: build/report/report.md (also .json, .html)"

# The parser fuzz runs at issue 12's scale here (100,000 mutated files, about 3 minutes); a bare
# `pytest` runs 3,000. Either scale is an environment variable (tests/test_fuzz.py).
MAX2CODE_FUZZ_EXAMPLES ?= 100000
export MAX2CODE_FUZZ_EXAMPLES

# make test is what CI runs: a tool the tests need and setup installs is a failure when missing,
# never a skip (tests/conftest.py: require).
test: setup
	CI=true $(PYTHON) -m pytest

# Speed against accuracy: root methods, Taylor model error, example scenes, the engine against
# pymunk and Box2D -> bench/results/ (setup installs the bench extra with the rest).
bench: setup
	$(PYTHON) bench/roots.py
	$(PYTHON) bench/engine.py

# The long runs of the property fuzzes (minutes): 2000 random engine worlds checked for
# tunnelling in exact geometry (tests/engine/tunnelling_long.py).
fuzz: setup
	PYTHONPATH=.:tests $(PYTHON) -m tests.engine.tunnelling_long --count 2000

clean:
	rm -rf build runtime/rust/target  # .venv stays: make distclean removes it too

distclean: clean
	rm -rf .venv
