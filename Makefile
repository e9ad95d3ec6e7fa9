# Thin wrapper over CMake. The two commands a new user needs:
#   make demo   install what is missing, build, run the default experiment
#   make test   install what is missing, build, run the whole test suite
BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
# Keeps the inner build's output free of make's directory chatter.
CMAKE_BUILD = env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL cmake --build $(BUILD) -j $(JOBS)

.PHONY: demo test configure deps clean

deps:
	@scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null

demo: configure
	@$(CMAKE_BUILD) --target hystbench
	@$(BUILD)/hystbench run benchmarks/experiments/demo.json --out $(BUILD)/demo --force

test: configure
	@$(CMAKE_BUILD)
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

clean:
	@rm -rf $(BUILD)
