# bearingheat: `make demo` and `make test` work on a fresh machine with only python3.
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
BH     := $(VENV)/bin/bearingheat
STAMP  := $(VENV)/.installed

.PHONY: demo test docs bench clean

$(STAMP): pyproject.toml
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[dev]'
	touch $(STAMP)

demo: $(STAMP)
	mkdir -p out
	$(BH) calc examples/gearbox_shaft.csv -o out/gearbox_shaft_results.csv --force
	$(BH) calc spreadsheets/gearbox_shaft_example.xlsx -o out/gearbox_shaft_results.xlsx --formulas --force
	@echo "Excel results: out/gearbox_shaft_results.xlsx, sheet 'Results' (live formulas: change n, Fr or nu on sheet 'Supports')"

test: $(STAMP)
	$(VENV)/bin/lint-imports --no-cache
	$(VENV)/bin/mypy bearingheat
	$(PY) -m pytest -q

docs: $(STAMP)
	$(PY) -m sphinx -W -q -b html docs docs/_build/html
	@echo "docs written to docs/_build/html/index.html"

bench: $(STAMP)
	$(PY) -m benchmarks

clean:
	rm -rf $(VENV) docs/_build build dist *.egg-info
