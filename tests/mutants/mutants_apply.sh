#!/usr/bin/env bash
# Every mutant of tests/mutants/mutants.txt still applies (its '- ' line
# occurs once in its file) and names tests the plan has: a stale mutant
# would only show when `make test-mutants` runs.
cd "$(dirname "$0")/../.."
python3 tests/mutants/mutants.py --check
