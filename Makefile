# Two commands set up a fresh machine: `make demo` and `make test` (ruff, mypy, tests with doctests).
# Both create a local virtual environment (.venv) and install everything into it.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: demo test lint bench clean postgres

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e ".[test]"
	touch $(STAMP)

demo: $(STAMP)
	$(BIN)/shaftline run examples/ntua_stern_tube.toml --out results/ntua_stern_tube
	@echo "Report: results/ntua_stern_tube/report.html"

test: $(STAMP) postgres
	$(BIN)/ruff check src tests benchmarks
	$(BIN)/mypy
	$(BIN)/python -m pytest -q

lint: $(STAMP)
	$(BIN)/ruff check src tests benchmarks
	$(BIN)/mypy

# Benchmarks run in their own environment, which also holds ROSS for the comparison.
bench:
	bash benchmarks/setup_env.sh
	.venv-bench/bin/python benchmarks/bench_bearing.py
	.venv-bench/bin/python benchmarks/bench_jfo.py
	.venv-bench/bin/python benchmarks/bench_sweep.py
	.venv-bench/bin/python benchmarks/bench_alignment.py
	.venv-bench/bin/python benchmarks/bench_wear.py
	.venv-bench/bin/python benchmarks/bench_cpp.py
	.venv-bench/bin/python benchmarks/bench_contact_qp.py
	.venv-bench/bin/python benchmarks/bench_coupled.py
	.venv-bench/bin/python benchmarks/bench_ntua_line.py
	.venv-bench/bin/python benchmarks/bench_design.py 10
	.venv-bench/bin/python benchmarks/bench_monitor.py
	.venv-bench/bin/python benchmarks/bench_startup.py

clean:
	rm -rf $(VENV) .venv-bench results .pytest_cache

# The trend store's PostgreSQL test starts a real server from Debian's package (tests/monitor/
# test_trends.py); installed here when missing and possible (root, Debian's registry reachable),
# otherwise that one test says why it is skipped.
postgres:
	@ls /usr/lib/postgresql/*/bin/initdb >/dev/null 2>&1 || command -v initdb >/dev/null 2>&1 || \
	  ( command -v apt-get >/dev/null 2>&1 && [ "$$(id -u)" = 0 ] && \
	    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq postgresql >/dev/null) ) || \
	  echo "PostgreSQL server not installed: the trend store's PostgreSQL test will be skipped"
