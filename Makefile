# The README's commands: `make setup`, `make test` (what CI runs: .ci/run), `make sheet` (the demo set)
# and `make docs` (the documentation site, build/site; tests/test_docs.py builds it too).
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin

.PHONY: setup tools sheet test docs bench clean

setup: $(VENV)/.installed tools

$(VENV)/.installed: pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install --quiet --upgrade pip
	$(BIN)/pip install --quiet -e '.[test,docs,cluster]'
	touch $@

tools:
	@scripts/install-tools

sheet: setup
	$(BIN)/derive sheet demo --out build/demo

docs: setup
	$(BIN)/mkdocs build --strict

test: setup
	$(BIN)/python -m pyflakes derive tests benchmarks docs/hooks.py
	# the package's bytecode written once: where PYTHONDONTWRITEBYTECODE is set (this machine's CI), each of
	# the hundreds of `derive` processes the tests start had compiled it afresh, half a second each
	$(BIN)/python -m compileall -q derive
	# one worker per core (pytest-xdist), an idle one taking tests queued for a busy one (worksteal):
	# the suite takes about 25 min on 2 cores, and prints its slowest tests, so that a test grown slow
	# shows. A fixed hash seed, so that a run can be repeated: sympy orders terms by string hashes
	PYTHONHASHSEED=0 $(BIN)/pytest -q -n auto --dist worksteal --durations=25

clean:
	rm -rf build .pytest_cache
