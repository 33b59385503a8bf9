# pcl_flowseg: the two commands of the README (demo, test) and the other targets.
#   make demo   installs dependencies, builds, and segments a shipped sample
#   make test   installs dependencies, builds, and runs the test suite
BUILD ?= build
JOBS ?= 2
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release

.PHONY: all deps build demo test install clean samples

all: build

deps:
	bash scripts/install_deps.sh

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	mkdir -p out
	$(BUILD)/apps/flowseg_segment samples/animal3d.pcd --output out/animal3d
	$(BUILD)/apps/flowseg_segment samples/hand2d.pcd --output out/hand2d

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

samples: build
	$(BUILD)/apps/flowseg_make_samples --output samples

install: build
	cmake --install $(BUILD)

clean:
	rm -rf $(BUILD) out
