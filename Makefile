# amigobot_tracking: one entry point for people and CI.
#   make demo   install, build, run the main job on the simulated robot
#   make test   install, build, run every test, end with `N passed, N failed`
# Debian's ROS tools need /usr/bin/python3, not another python3 earlier on PATH.
export PATH := /usr/bin:$(PATH)
SHELL := /bin/bash
ROOT := $(abspath $(dir $(lastword $(MAKEFILE_LIST))))
WS := $(ROOT)/.ws
JOBS ?= 2
CATKIN := catkin_make -C $(WS) -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=Release -j$(JOBS)
SETUP := source $(WS)/devel/setup.bash
RESULTS := $(WS)/build/test_results

.PHONY: deps build test demo bench fuzz clean

deps:
	@$(ROOT)/scripts/install_deps.sh

$(WS)/src/amigobot_tracking:
	mkdir -p $(WS)/src
	ln -sfn $(ROOT) $(WS)/src/amigobot_tracking

build: deps $(WS)/src/amigobot_tracking
	$(CATKIN)

test: build
	rm -rf $(RESULTS)
	$(CATKIN) tests
	-$(CATKIN) run_tests
	-$(ROOT)/scripts/run_fuzz.sh 30 $(RESULTS)
	@$(ROOT)/scripts/count_test_results.py $(RESULTS)

demo: build
	$(WS)/devel/lib/amigobot_tracking/closed_loop_demo

bench: build
	$(CATKIN) bench_core
	$(SETUP) && $(WS)/devel/lib/amigobot_tracking/bench_core --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
	$(CATKIN) bench_aria
	$(WS)/devel/lib/amigobot_tracking/bench_aria

# Longer libFuzzer run of the ARIA packet parser (ASan + UBSan): make fuzz FUZZ_SECONDS=600
FUZZ_SECONDS ?= 600
fuzz: deps
	$(ROOT)/scripts/run_fuzz.sh $(FUZZ_SECONDS)

clean:
	rm -rf $(WS)
