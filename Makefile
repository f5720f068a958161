# The two commands of the README: `make` (generate every shipped equation in every language into
# build/, with a summary, and the variant report in build/report/) and `make test`. Both install
# what is missing first (scripts/setup).
PYTHON ?= python3

.PHONY: all build test setup clean bench

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

test: setup
	$(PYTHON) -m pytest

# Speed against accuracy: root methods, Taylor model error, example scenes, the engine against
# pymunk and Box2D -> bench/results/ (the bench extra, installed here when missing).
bench: setup
	$(PYTHON) -c "import numpy, matplotlib, mpmath, pymunk, Box2D" 2>/dev/null || \
	    $(PYTHON) -m pip install -q --disable-pip-version-check --root-user-action=ignore -e '.[bench]'
	$(PYTHON) bench/roots.py
	$(PYTHON) bench/engine.py

clean:
	rm -rf build runtime/rust/target
