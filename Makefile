# Thin wrapper: dependencies -> configure -> build -> run/test.
PRESET ?= release
BUILD  := build/$(PRESET)
JOBS   ?= $(shell nproc)
SCENE  ?= cases/abrasive_flow_machining/scene.yaml
OUT    ?= out/$(notdir $(patsubst %/,%,$(dir $(SCENE))))

.PHONY: deps configure build run test bench format clean

deps:
	@bash scripts/install-deps

$(BUILD)/build.ninja: | deps
	cmake --preset $(PRESET)

configure: deps $(BUILD)/build.ninja

build: configure
	cmake --build $(BUILD) -j $(JOBS)

run: build
	$(BUILD)/monosph run $(SCENE) --out $(OUT)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) --timeout 1500

bench: build
	$(BUILD)/monosph bench --json out/bench.json

format:
	clang-format -i $$(git ls-files '*.cpp' '*.hpp')

clean:
	rm -rf build
