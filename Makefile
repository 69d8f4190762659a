# flexbooster: two commands from a fresh machine -- `make run` and `make test`.
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed
OUT    ?= flexbooster-results

.PHONY: run test lint bench clean venv

venv: $(STAMP)

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[test]'
	touch $(STAMP)

run: export OPENBLAS_NUM_THREADS = 1
run: $(STAMP)
	$(VENV)/bin/flexbooster run -o $(OUT)

lint: $(STAMP)
	$(VENV)/bin/ruff check .

test: export OPENBLAS_NUM_THREADS = 1
test: $(STAMP)
	$(VENV)/bin/ruff check .
	$(PY) -m pytest -q

bench: export OPENBLAS_NUM_THREADS = 1
bench: $(STAMP)
	@for f in benchmarks/bench_*.py; do echo "== $$f"; $(PY) $$f || exit 1; done

clean:
	rm -rf $(VENV) $(OUT) build *.egg-info src/*.egg-info .pytest_cache .ruff_cache
