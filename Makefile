# ArtiMo — the two fresh-machine commands are `make demo` and `make test`.
# Both are idempotent: they install only what is missing.

PYTHON ?= python3
VENV   ?= .venv
PY     := $(VENV)/bin/python
PIP    := $(VENV)/bin/pip
EXTRAS ?= render,models,bench,service,usd,mjcf,dev
VALIDATOR_DIR := tests/tools/gltf_validator
WEB_DIR := app/web
DEMO_OUT ?= out/demo
DEMO_CLI_OUT ?= out/demo-cli
PYTEST_ARGS ?=

export PYOPENGL_PLATFORM ?= egl

.PHONY: setup system-deps venv validator web browser services demo test lint clean help

help:
	@echo "make demo   - set up everything, animate an example with the CLI, then submit it to the embedded service (artimo serve) and download the GLB"
	@echo "             (then: artimo serve prints the page's signed-in link)"
	@echo "make test   - set up everything, run the whole test suite"
	@echo "make lint   - ruff + mypy + import contracts"

setup: system-deps venv validator web

system-deps:
	@.ci/system-deps.sh

venv: $(VENV)/.installed

$(VENV)/.installed: pyproject.toml
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PIP) install --quiet -e '.[$(EXTRAS)]'
	touch $@

validator: $(VALIDATOR_DIR)/node_modules/.installed

$(VALIDATOR_DIR)/node_modules/.installed: $(VALIDATOR_DIR)/package.json
	npm install --prefix $(VALIDATOR_DIR) --no-audit --no-fund --loglevel=error
	touch $@

# three.js, Swagger UI and Redoc for the page and the API docs, from the npm registry into the served folder
web: $(WEB_DIR)/node_modules/.installed

$(WEB_DIR)/node_modules/.installed: $(WEB_DIR)/package.json $(WEB_DIR)/package-lock.json
	npm ci --prefix $(WEB_DIR) --no-audit --no-fund --loglevel=error --ignore-scripts --legacy-peer-deps
	touch $@

# Debian's Chromium for the browser tests (never a downloaded browser build)
browser:
	@.ci/browser-deps.sh

services:
	@.ci/services.sh

demo: setup
	$(VENV)/bin/artimo animate examples/pedal_bin --prompt "press the pedal to open the bin" --out $(DEMO_CLI_OUT)
	$(PY) -m tests.support.gltf_validator $(DEMO_CLI_OUT)/animation.glb
	VENV=$(VENV) DEMO_OUT=$(DEMO_OUT) .ci/demo-service.sh

test: setup services browser
	$(PY) -m pytest -q $(PYTEST_ARGS)

lint: venv
	$(VENV)/bin/ruff check app workers benchmark tests
	$(VENV)/bin/mypy
	$(VENV)/bin/lint-imports

clean:
	rm -rf out .pytest_cache
