# `make all` sets up .venv when needed, runs the whole pipeline on the default split and prints the accuracy table.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
SPLIT ?= small
WORKERS ?= 2

.PHONY: all setup test smoke bench realistic ray clean

all: $(STAMP)
	$(BIN)/dynclevr run --split $(SPLIT) --workers $(WORKERS)
	$(BIN)/dynclevr report --split $(SPLIT)

setup: $(STAMP)

# torch first and pinned, so that no other requirement can pull a CUDA build.
$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install -q --disable-pip-version-check torch==2.13.0
	$(BIN)/pip install -q --disable-pip-version-check -e '.[test]'
	touch $(STAMP)

# One process per worker (WORKERS, one per core); a file's tests stay together, so its module fixtures (the smoke
# runs) are made once.
test: $(STAMP)
	$(BIN)/pytest -n $(WORKERS) --dist loadfile

smoke: $(STAMP)
	$(BIN)/dynclevr run --split tiny --workers $(WORKERS) --data-dir data
	$(BIN)/dynclevr report --split tiny

bench: $(STAMP)
	$(BIN)/python -m benchmarks

# The realistic render backend (render.backend = "mitsuba"): Mitsuba 3's LLVM variant needs libLLVM (Debian's 19).
realistic: $(STAMP)
	@ls /usr/lib/x86_64-linux-gnu/libLLVM-19.so* >/dev/null 2>&1 || ! command -v apt-get >/dev/null || \
		{ apt-get install -y -q libllvm19 || { apt-get update -q && apt-get install -y -q libllvm19; }; }
	$(BIN)/pip install -q --disable-pip-version-check -e '.[realistic]'
	$(BIN)/python -c "from dynclevr.render.mitsuba import require_mitsuba; require_mitsuba(); print('mitsuba ready')"

# The Ray executor (`dynclevr run --executor ray [--ray-address auto]`): an optional extra, as the realistic backend.
ray: $(STAMP)
	$(BIN)/pip install -q --disable-pip-version-check -e '.[ray]'
	$(BIN)/python -c "import ray; print('ray', ray.__version__, 'ready')"

clean:
	rm -rf data/tiny data/small
