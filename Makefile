# Thin wrapper over CMake. The two commands a new user needs:
#   make demo   install what is missing, build the program and the Python module,
#               run the default experiment
#   make test   install what is missing, build (failing on any compiler warning),
#               run the whole test suite
#   make paper  build, then regenerate results/paper/ (the seed papers' comparisons)
#   make test-quick  build, then the tests labelled unit and integration (not the
#                    slow hidden-effect cases): about a minute, for the edit loop
BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
# Keeps the inner build's output free of make's directory chatter.
CMAKE_BUILD = env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL cmake --build $(BUILD) -j $(JOBS)

.PHONY: demo test test-quick paper configure deps clean

deps:
	@scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null

demo: configure
	@$(CMAKE_BUILD) --target demo_programs
	@$(BUILD)/hystbench run benchmarks/experiments/demo.json --out $(BUILD)/demo --force

test: configure
	@scripts/build-without-warnings.sh $(BUILD) $(JOBS)
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

test-quick: configure
	@$(CMAKE_BUILD)
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE discovery

paper: configure
	@$(CMAKE_BUILD) --target hystbench
	@benchmarks/paper.sh $(BUILD)/hystbench

clean:
	@rm -rf $(BUILD)
