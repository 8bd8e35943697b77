# Two commands do all set-up on a fresh machine with Python 3.11+ and pip:
#   make run   - the main job: reproduce the study, report in study-report/
#   make test  - the whole test suite: ruff, mypy on src/, the import contracts, the
#                documentation site built with warnings as errors (make docs), pytest with
#                doctests and the code blocks of README.md and docs/*.md (Sybil; it
#                also opens the built site in a browser, offline)
#                (make test-fast: the same without the tests marked slow and the docs)
PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

# The browser tests drive Debian's Chromium (Playwright's own download cannot be
# fetched everywhere); test installs it when it is missing, with sudo unless root.
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: run test test-fast docs clean chromium linuxcnc

$(STAMP): pyproject.toml src/ballscrew/_version.py
	$(PYTHON) -c 'import sys; sys.exit("Python >= 3.11 is required, found " + sys.version.split()[0]) if sys.version_info < (3, 11) else None'
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --disable-pip-version-check --upgrade pip
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -e '.[test,docs]'
	touch $(STAMP)

run: $(STAMP)
	$(BIN)/ballscrew study --out study-report

test: $(STAMP) chromium linuxcnc
	$(BIN)/ruff check src tests benchmarks examples scripts conftest.py
	$(BIN)/ruff format --check src tests benchmarks examples scripts conftest.py
	$(BIN)/mypy src
	$(BIN)/lint-imports
	$(MAKE) docs
	$(BIN)/pytest -q

# The documentation site in docs/_build/html: the API reference, the Markdown pages and
# the gallery (examples/plot_*.py run), the notebooks (run), and the pictures of docs/img
# redrawn from this version (scripts/docs_figures.py, the web pages in Chromium); a
# warning fails the build.
docs: $(STAMP) chromium
	rm -rf docs/_build docs/api docs/gallery docs/sg_execution_times.rst
	$(BIN)/sphinx-build -W --keep-going -q -b html docs docs/_build/html
	$(BIN)/python scripts/check_api_docs.py docs/_build/html
	@echo "docs: docs/_build/html/index.html"

test-fast: $(STAMP)
	$(BIN)/ruff check src tests benchmarks examples scripts conftest.py
	$(BIN)/mypy src
	$(BIN)/lint-imports
	$(BIN)/pytest -q -m "not slow"

chromium:
	@if command -v chromium >/dev/null 2>&1; then :; \
	elif command -v apt-get >/dev/null 2>&1; then \
	  echo "installing Debian's chromium for the browser tests"; \
	  $(SUDO) apt-get -o DPkg::Lock::Timeout=600 update -qq && \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y -qq chromium >/dev/null; \
	else \
	  echo "note: no chromium and no apt-get: the browser tests are skipped (they fail on CI)"; \
	fi

# The LinuxCNC friction tables are loaded in a real HAL session (halrun) by the tests, and
# LinuxCNC's interpreter rs274 reads part programs (ballscrew program --reader rs274);
# test installs Debian's linuxcnc-uspace when either is missing, like chromium, without
# the recommended packages (they pull a real-time kernel; both tools are in the package).
linuxcnc:
	@if command -v halrun >/dev/null 2>&1 && command -v rs274 >/dev/null 2>&1; then :; \
	elif command -v apt-get >/dev/null 2>&1; then \
	  echo "installing Debian's linuxcnc-uspace for the HAL and rs274 tests"; \
	  $(SUDO) apt-get -o DPkg::Lock::Timeout=600 update -qq && \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y -qq --no-install-recommends linuxcnc-uspace >/dev/null; \
	else \
	  echo "note: no halrun/rs274 and no apt-get: their tests are skipped (they fail on CI)"; \
	fi

clean:
	rm -rf $(VENV) build *.egg-info src/*.egg-info .pytest_cache .mypy_cache .ruff_cache test-output
	rm -rf docs/_build docs/api docs/gallery docs/sg_execution_times.rst
