# Two commands for a fresh machine: `make demo` and `make test`.
PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed-$(shell cat pyproject.toml | cksum | cut -d' ' -f1)
# Optional parts installed by `make install` (README, "Installing parts"):
# every extra but llm-local, which builds llama-cpp-python from source (about
# 8 minutes on 2 cores the first time; pip caches the wheel). Opt in with
# `make llm-local` (adds it to the venv) or `make install EXTRAS=all,test,llm-local`;
# without it the tests of the local LLM server skip, naming what is missing.
EXTRAS ?= all,test
export HF_HUB_OFFLINE := 1
export TRANSFORMERS_OFFLINE := 1
export MUJOCO_GL ?= osmesa
export PYOPENGL_PLATFORM ?= osmesa

.PHONY: install system-deps demo-deps llm-local demo demo-arm check test golden golden-parse bench bench-suites bench-language llm-eval clean

$(STAMP): pyproject.toml
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install -q --upgrade pip
	# The CPU build of PyTorch first, so nothing pulls the multi-GB CUDA build.
	$(PY) -m pip install -q torch==2.13.0
	$(PY) -m pip install -q -e ".[$(EXTRAS)]"
	# The sentence model to ONNX, once (the only use of torch; see lgmcts/language/export.py).
	$(PY) -m lgmcts.language.export --quiet
	@rm -f $(VENV)/.installed-*
	@touch $(STAMP)

install: $(STAMP)

system-deps:
	@bash scripts/system-deps.sh

# What the demo needs of the system: OpenGL for MuJoCo (no browser, no ffmpeg).
demo-deps:
	@bash scripts/system-deps.sh demo

# The local OpenAI-compatible server for --parser llm and LFSP (opt-in, slow to
# build: see EXTRAS above). Installs the llm-local extra into the venv.
llm-local: install
	$(PY) -m pip install -q -e ".[llm-local]"

demo: install demo-deps
	@mkdir -p out/demo
	$(PY) -m lgmcts plan examples/tabletop.json \
	    "$(DEMO_COMMAND)" \
	    --seed 0 -o out/demo/plan.json --viz out/demo
	@cat out/demo/plan.json
	$(PY) -m lgmcts execute examples/tabletop.json out/demo/plan.json
	$(demo-arm-steps)
	@echo "pictures: out/demo/initial.png, out/demo/final.png, out/demo/before_after.png, out/demo/plan.gif, out/demo/heatmaps_step_01.png"
	@echo "the UR5e arm: out/demo/arm.mp4 (its plan: out/demo/plan_arm.json)"

# The example played by a UR5e arm with a suction cup (docs/sim.md): a plan
# for the arm's reach and a small video of its execution next to the demo
# pictures (320x240 at 15 frames per simulated second: 4.4 s for both steps on
# 2 cores, where a 640x480 video at 25 alone takes 7-8 s; docs/sim.md).
# `make demo` runs these steps too.
DEMO_COMMAND := Move all blocks into a circle; while put the white bottle behind one block
define demo-arm-steps
$(PY) -m lgmcts plan examples/tabletop.json "$(DEMO_COMMAND)" --seed 0 --robot ur5e -o out/demo/plan_arm.json
$(PY) -m lgmcts execute examples/tabletop.json out/demo/plan_arm.json --robot ur5e \
    --video out/demo/arm.mp4 --video-size 320x240 --video-fps 15
endef

demo-arm: install demo-deps
	@mkdir -p out/demo
	$(demo-arm-steps)
	@echo "video: out/demo/arm.mp4"

# Lint (ruff), types (mypy) and the quick tests (-m "not slow", about 80 s on
# 2 cores); what each leaves out and why: docs/design.md, "Lint and types".
# The Debian packages first, as for `make test`: on a machine without OSMesa the
# quick tests of the simulator could not even be collected.
check: install system-deps
	$(PY) -m ruff check .
	$(PY) -m mypy
	$(PY) -m pytest tests -m "not slow"

test: install system-deps
	$(PY) -m pytest tests

# Rewrite tests/data/golden_plans.json: only when a change is meant to alter plans.
golden: install
	$(PY) tests/core/golden.py --write

# Rewrite tests/data/golden_parses.json: only when a change is meant to alter what
# the offline parser reads (or the reason of a refusal); say why in the commit.
golden-parse: install
	$(PY) tests/language/golden_parse.py --write

bench: install
	$(PY) benchmarks/planner.py random --n 300
	$(PY) benchmarks/planner.py labbe --per-n 100
	$(PY) benchmarks/planner.py memory --objects 40

bench-suites: install system-deps
	$(PY) benchmarks/suite_figures.py

# Cold start and parse time of the offline parser (docs/benchmarks.md).
bench-language: install
	$(PY) benchmarks/language_runtime.py --runs 5

# The LLM parser and LFSP on a local server (llama-cpp-python + Gemma 3 270M on
# 127.0.0.1): every language evaluation set through --parser llm, and LFSP on
# both suites. LLM_EVAL_ARGS="--every 10 --lfsp-n 10" for a quicker sample.
LLM_EVAL_ARGS ?=
llm-eval: llm-local
	$(PY) benchmarks/llm_eval.py $(LLM_EVAL_ARGS)

clean:
	rm -rf out .pytest_cache
