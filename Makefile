# flexbooster: two commands from a fresh machine -- `make run` and `make test`.
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed
OUT    ?= flexbooster-results

.PHONY: run test test-fast lint bench clean venv test-browser browser fuzz

venv: $(STAMP)

# constraints.txt: the versions the suite was last run with (pyproject.toml keeps the ranges)
$(STAMP): pyproject.toml constraints.txt
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -c constraints.txt -e '.[test]'
	touch $(STAMP)

run: export OPENBLAS_NUM_THREADS = 1
run: $(STAMP)
	$(VENV)/bin/flexbooster run -o $(OUT)

lint: $(STAMP)
	$(VENV)/bin/ruff check .

# The whole suite (what CI runs); `test-fast` leaves out the tests marked slow (the edit loop).
# Both in parallel on every CPU; worksteal: an idle worker takes tests queued for a busy one.
test: export OPENBLAS_NUM_THREADS = 1
test: $(STAMP)
	$(VENV)/bin/ruff check .
	$(PY) -m pytest -q -rs -n auto --dist worksteal --durations=15

test-fast: export OPENBLAS_NUM_THREADS = 1
test-fast: $(STAMP)
	$(VENV)/bin/ruff check .
	$(PY) -m pytest -q -rs -n auto --dist worksteal -m "not slow" --durations=10

# The report in headless Chromium alone (`make test` runs it too, and .ci/run calls `make
# browser` first so that CI does): `browser` installs Debian's chromium and chromium-driver
# (apt-get, as root or via sudo) and selenium (the `browser` extra) into the venv.
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo -n)
# Best effort (used by .ci/run): chromium + chromium-driver by apt-get when root or passwordless
# sudo is available, selenium into the venv; says why and succeeds when it cannot.
browser: $(STAMP)
	@if command -v chromium >/dev/null && command -v chromedriver >/dev/null; then \
	  echo "browser: chromium and chromedriver already installed"; \
	elif ! command -v apt-get >/dev/null; then \
	  echo "browser: no apt-get on this machine: the browser tests will skip"; \
	elif [ "$$(id -u)" != 0 ] && ! sudo -n true 2>/dev/null; then \
	  echo "browser: neither root nor passwordless sudo: the browser tests will skip"; \
	else \
	  { $(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install \
	      -y -qq --no-install-recommends chromium chromium-driver >/dev/null; } || \
	  echo "browser: apt-get install chromium chromium-driver failed: the browser tests will skip"; \
	fi
	@$(PY) -m pip install --quiet -c constraints.txt -e '.[test,browser]' || \
	  echo "browser: pip install selenium failed: the browser tests will skip"

test-browser: export OPENBLAS_NUM_THREADS = 1
test-browser: browser
	$(PY) -m pytest -q -rs tests/test_browser.py tests/test_report.py

# The long property-based fuzz (hypothesis, fixed seed): 1,000 valid cases over the
# documented input space through the API and 1,000 invalid ones; prints the counts (ok,
# documented errors, internal errors, NaN, over the budget) and fails unless the last three
# are 0.  `make test` runs the same file with a bounded number of examples.  A third of the
# valid cases have a [vehicle] table (segments with loads and stiffeners, masses, a tank), one
# in five runs the vehicle's regions (budget 20 s), those with segments through a [flight].
# About an hour on the shared 2-core machine at load 4-6 (the flights, the vehicle regions);
# FLEXBOOSTER_FUZZ_EXAMPLES=200 for a shorter run, FLEXBOOSTER_FUZZ_LOG=FILE for one line per
# case (time, outcome, regions, case); the budget is each case's CPU time.
fuzz: export OPENBLAS_NUM_THREADS = 1
fuzz: export FLEXBOOSTER_FUZZ = long
fuzz: $(STAMP)
	$(PY) -m pytest -q -s -p no:cacheprovider tests/test_fuzz.py

bench: export OPENBLAS_NUM_THREADS = 1
bench: $(STAMP)
	@for f in benchmarks/bench_*.py; do echo "== $$f"; $(PY) $$f || exit 1; done

clean:
	rm -rf $(VENV) $(OUT) build *.egg-info src/*.egg-info .pytest_cache .ruff_cache
