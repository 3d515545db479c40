# Two commands on a fresh machine: `make run` and `make test`.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: run test fuzz bench snapshot-update clean

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $(STAMP)

run: $(STAMP)
	$(BIN)/hmi

test: $(STAMP)
	$(BIN)/python -m pytest -q -n 2 -p no:cacheprovider

fuzz: $(STAMP)
	$(BIN)/python -m pytest -q -m fuzz -p no:cacheprovider
	ISO_RS274_PROGRAMS=600 $(BIN)/python -m pytest -q -n 2 -p no:cacheprovider tests/iso/test_rs274_diff.py

bench: $(STAMP)
	$(BIN)/python -m bench

snapshot-update: $(STAMP)
	$(BIN)/python -m pytest -q --snapshot-update tests/hmi

clean:
	rm -rf $(VENV) build dist *.egg-info
