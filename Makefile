# Two commands on a fresh machine: `make run` and `make test`.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
# Byte-compile the project before starting it: some shells set PYTHONDONTWRITEBYTECODE,
# and then every start would compile all modules again (~0.3 s). Only changed files
# are compiled; stale bytecode is never used (Python checks the source's time stamp).
COMPILE := $(BIN)/python -m compileall -q nck hmi screens bench >/dev/null

.PHONY: run test fuzz bench snapshot-update clean browser rs274

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[test,serve]'
	touch $(STAMP)

run: $(STAMP)
	$(COMPILE)
	$(BIN)/hmi

# Three workers on two cores, work stealing: the Pilot, subprocess and browser tests spend part of
# their time waiting, and a third worker fills it (clean clone, idle: 9 min 10 s with -n 2,
# 7 min 28 s with -n 3 --dist worksteal).
# PYTHONDONTWRITEBYTECODE cleared: pytest then keeps its assertion-rewritten test modules in
# __pycache__ (it reads them even when the variable is set, but writes them only when it is not);
# without them every worker rewrites all 400 test modules at every run (about 10 s of CPU each).
test: $(STAMP) browser
	$(COMPILE)
	PYTHONDONTWRITEBYTECODE= $(BIN)/python -m pytest -q -n 3 --dist worksteal -p no:cacheprovider --durations=15

# Headless Chromium for the browser test of `hmi --serve` (tests/hmi/test_browser.py):
# Debian's packages, installed when make runs as root (CI does); elsewhere the test is skipped.
browser:
	@if ! command -v chromium >/dev/null || ! command -v chromedriver >/dev/null; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
	    echo "make: installing chromium and chromium-driver for the browser test"; \
	    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium chromium-driver >/dev/null) \
	      || echo "make: Chromium could not be installed: the browser test will be skipped"; \
	  else \
	    echo "make: no Chromium (apt-get install chromium chromium-driver as root): the browser test will be skipped"; \
	  fi; \
	fi

# LinuxCNC's stand-alone interpreter for the differential fuzzing against rs274 (tests/iso/
# test_rs274_diff.py, tests/bench): Debian's linuxcnc-uspace, installed when make runs as root.
# `make test` does not install it (a few minutes of download); without it those comparisons are
# skipped there and run here.
rs274:
	@if ! command -v rs274 >/dev/null; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
	    echo "make: installing linuxcnc-uspace for the comparison with rs274"; \
	    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq linuxcnc-uspace >/dev/null) \
	      || echo "make: linuxcnc-uspace could not be installed: the rs274 comparisons will be skipped"; \
	  else \
	    echo "make: no rs274 (apt-get install linuxcnc-uspace as root): the rs274 comparisons will be skipped"; \
	  fi; \
	fi

# The long fuzz tests run for many minutes each: the suite's hang watchdog (tests/conftest.py,
# 7 minutes for `make test`) gets two hours here.
fuzz: $(STAMP) rs274
	NCK_TEST_HANG_S=7200 $(BIN)/python -m pytest -q -m fuzz -p no:cacheprovider -o timeout=0 --hypothesis-profile=fuzz
	NCK_TEST_HANG_S=7200 ISO_RS274_PROGRAMS=600 $(BIN)/python -m pytest -q -n 2 -p no:cacheprovider -o timeout=0 --hypothesis-profile=fuzz tests/iso/test_rs274_diff.py

bench: $(STAMP)
	$(COMPILE)
	$(BIN)/python -m bench

snapshot-update: $(STAMP)
	$(BIN)/python -m pytest -q --snapshot-update tests/hmi

clean:
	rm -rf $(VENV) build dist *.egg-info
