#!/usr/bin/env bash
# The benchmarks' own environment: shaftline plus ROSS for the side-by-side comparison.
# ROSS 3.x declares Python >= 3.13; on 3.11 it installs with --no-deps
# --ignore-requires-python, and we install the dependencies its bearing code imports
# (ccp-performance is imported by ROSS's seal module at package import).
set -euo pipefail
cd "$(dirname "$0")/.."
PYTHON=${PYTHON:-python3}
if [ ! -x .venv-bench/bin/python ]; then
  "$PYTHON" -m venv .venv-bench
  .venv-bench/bin/python -m pip install --quiet --upgrade pip
fi
.venv-bench/bin/python -m pip install --quiet -e .
.venv-bench/bin/python -m pip install --quiet pandas plotly xlrd methodtools numba prettytable control toml ccp-performance
.venv-bench/bin/python -m pip install --quiet --no-deps --ignore-requires-python "ross-rotordynamics>=3,<4"
