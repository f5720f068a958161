# The two commands of the README: `make` (generate every shipped equation in every language into
# build/, with a summary) and `make test`. Both install what is missing first (scripts/setup).
PYTHON ?= python3

.PHONY: all build test setup clean bench

all: build

setup:
	./scripts/setup

build: setup
	$(PYTHON) -m max2code build -o build

test: setup
	$(PYTHON) -m pytest

# Speed against accuracy: root methods, Taylor model error, example scenes -> bench/results/
# (needs numpy and matplotlib: pip install -e .[bench]).
bench: setup
	$(PYTHON) bench/roots.py

clean:
	rm -rf build runtime/rust/target
