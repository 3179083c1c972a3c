# rayscad — hand-written Makefile.
#   make          build build/rayscad
#   make deps     install the Debian packages (apt-get), only those missing
#   make demo     deps + build + render models/demo.scad to out/demo.png
#   make test     deps + build + every test (unit, language, against OpenSCAD)
#   make asan     the same tests on a -fsanitize=address,undefined build
#   make bench    rayscad against povray, openscad and manifold-3d (bench/run.py)
# WERROR=1 turns warnings into errors (CI).

CC  ?= cc
CXX ?= c++
BUILD ?= build
OPT ?= -O2 -g

WARN = \
	-Wall \
	-Wextra \
	-Wpedantic \
	-Wshadow \
	-Wstrict-prototypes \
	-Wmissing-prototypes \
	-Wno-unused-parameter

CXXWARN = \
	-Wall \
	-Wextra \
	-Wno-maybe-uninitialized \
	-Wno-deprecated-copy

ifeq ($(WERROR),1)
WARN += -Werror
CXXWARN += -Werror
endif

SANFLAGS =
ifeq ($(SAN),1)
SANFLAGS = -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
endif

CFLAGS   = -std=c11 -D_POSIX_C_SOURCE=200809L $(OPT) $(WARN) $(SANFLAGS) -MMD -MP
CXXFLAGS = -std=c++17 $(OPT) $(CXXWARN) $(SANFLAGS) -MMD -MP \
	$(shell pkg-config --cflags OpenImageIO 2>/dev/null) \
	$(shell pkg-config --cflags polyclipping freetype2 harfbuzz fontconfig 2>/dev/null)
LDLIBS   = $(shell pkg-config --libs OpenImageIO 2>/dev/null) -lOpenMeshCore -lOpenMeshTools \
	$(shell pkg-config --libs polyclipping freetype2 harfbuzz fontconfig 2>/dev/null) \
	-lpthread -lm

DEBS = openscad xvfb xauth povray libopenimageio-dev openimageio-tools libopenmesh-dev \
	libcriterion-dev pkg-config g++ make \
	libpolyclipping-dev libfreetype-dev libharfbuzz-dev libfontconfig-dev fonts-liberation

LIB_SRC  = $(wildcard src/intervals/*.c src/csg/*.c src/scad/*.c src/render/*.c src/mesh/*.c)
IO_SRC   = $(wildcard src/io/*.cpp)
CLI_SRC  = $(wildcard src/cli/*.c)
TEST_SRC = $(wildcard tests/test_*.c)
TOOL_SRC = $(wildcard tests/tools/*.c)

LIB_OBJ  = $(LIB_SRC:%.c=$(BUILD)/obj/%.o) $(IO_SRC:%.cpp=$(BUILD)/obj/%.o)
CLI_OBJ  = $(CLI_SRC:%.c=$(BUILD)/obj/%.o)
# the command's parts that tests and tools use too (its services, writers)
CLI_LIB_OBJ = $(filter-out $(BUILD)/obj/src/cli/main.o,$(CLI_OBJ))
TESTS    = $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
TOOLS    = $(TOOL_SRC:tests/tools/%.c=$(BUILD)/tools/%)

.PHONY: all deps demo test unit cli compare conformance meshcheck asan clean format bench
.DEFAULT_GOAL := all

all: $(BUILD)/rayscad $(TESTS) $(TOOLS)

$(BUILD)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -c $< -o $@

$(BUILD)/obj/%.o: %.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -c $< -o $@

$(BUILD)/librayscad.a: $(LIB_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	ar rcs $@ $^

$(BUILD)/rayscad: $(CLI_OBJ) $(BUILD)/librayscad.a
	$(CXX) $(SANFLAGS) -o $@ $^ $(LDLIBS)

$(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $(CLI_LIB_OBJ) $(BUILD)/librayscad.a
	@mkdir -p $(dir $@)
	$(CXX) $(SANFLAGS) -o $@ $^ -lcriterion $(LDLIBS)

$(BUILD)/tools/%: $(BUILD)/obj/tests/tools/%.o $(CLI_LIB_OBJ) $(BUILD)/librayscad.a
	@mkdir -p $(dir $@)
	$(CXX) $(SANFLAGS) -o $@ $^ $(LDLIBS)

deps:
	@missing=""; for p in $(DEBS); do \
		dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
		echo "installing:$$missing"; \
		apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing >/dev/null; \
	fi

demo: deps
	$(MAKE) $(BUILD)/rayscad
	@mkdir -p out
	$(BUILD)/rayscad models/demo.scad -o out/demo.png --samples 3 \
		$$(sed -n 's|^// args: *||p' models/demo.scad)
	@echo "wrote out/demo.png"

unit: all
	@fail=0; for t in $(TESTS); do $$t --jobs=2 || fail=1; done; exit $$fail

cli: all
	tests/cli_test.sh $(BUILD)

compare: all
	tests/compare_openscad.sh $(BUILD)

conformance: all
	tests/conformance.sh $(BUILD)

meshcheck: all
	tests/mesh_compare.sh $(BUILD)

test: deps
	$(MAKE) all
	$(MAKE) unit
	$(MAKE) cli
	$(MAKE) conformance
	$(MAKE) meshcheck
	$(MAKE) compare

asan: deps
	$(MAKE) BUILD=build-asan SAN=1 OPT="-O1 -g" all
	$(MAKE) BUILD=build-asan SAN=1 OPT="-O1 -g" unit
	$(MAKE) BUILD=build-asan SAN=1 OPT="-O1 -g" cli
	$(MAKE) BUILD=build-asan SAN=1 OPT="-O1 -g" conformance
	$(MAKE) BUILD=build-asan SAN=1 OPT="-O1 -g" meshcheck
	$(MAKE) BUILD=build-asan SAN=1 OPT="-O1 -g" compare

# Benchmarks against povray, openscad and manifold-3d (not a test; bench/run.py).
bench: deps
	$(MAKE) all
	@test -d bench/node_modules/manifold-3d || (cd bench && npm install --no-audit --no-fund) || \
		echo "bench: npm install failed; meshing runs without manifold-3d"
	python3 bench/run.py $(BUILD)

format:
	clang-format -i $(LIB_SRC) $(CLI_SRC) $(TEST_SRC) $(TOOL_SRC) $(IO_SRC) src/*/*.h

clean:
	rm -rf build build-asan out

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
