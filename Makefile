# rayscad — hand-written Makefile.
#   make          build build/rayscad
#   make deps     install the Debian packages (apt-get), only those missing
#   make demo     deps + build + render models/demo.scad to out/demo.png
#   make test     deps + build + every test (unit, language, against OpenSCAD)
#   make asan     the same tests on a -fsanitize=address,undefined,float-cast-overflow build
#   make bench    rayscad against povray, openscad and manifold-3d (bench/run.py)
# WERROR=1 turns warnings into errors (CI).

CC  ?= cc
CXX ?= c++
BUILD ?= build
OPT ?= -O3 -g

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
SANFLAGS = -fsanitize=address,undefined,float-cast-overflow -fno-omit-frame-pointer -fno-sanitize-recover=undefined,float-cast-overflow
# lib3mf's own leaks (tests/lsan.supp says which)
export LSAN_OPTIONS ?= suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0
# LeakSanitizer's tracer reads a bogus dynamic-TLS range (0x1f2d..0x100000302f)
# and dies with signal 11 after the image adapter is dlopened in a process
# that also links libxml2, libzip and lib3mf (module_recursion.scad, every
# time): it no longer tracks __tls_get_addr blocks, which hold no heap roots
# of ours.
export ASAN_OPTIONS ?= detect_leaks=1:intercept_tls_get_addr=0
endif

# No build path in what is built (debug information names files from here),
# so an installed binary or library says nothing of the tree it came from.
PREFIX_MAP = -ffile-prefix-map=$(CURDIR)=.

# GCC 12.2 (Debian 12's) basic-block SLP drops a double's rounding to float
# and back when it vectorizes two or more in a row (x[i] = (float)x[i]: x[0]
# and x[1] kept unrounded at -O3, rounded at -O2); the mesher rounds corners
# to the float places its vertices will hold, so -O3 and the sanitizer
# build's -O1 made different meshes.  tests/mesh/test_float_round.c checks it.
NOSLP = -fno-tree-slp-vectorize

CFLAGS   = -std=c11 -D_POSIX_C_SOURCE=200809L $(OPT) $(NOSLP) $(WARN) $(SANFLAGS) $(PREFIX_MAP) -MMD -MP \
	$(shell pkg-config --cflags libxml-2.0 2>/dev/null)
CXXFLAGS = -std=c++17 $(OPT) $(NOSLP) $(CXXWARN) $(SANFLAGS) $(PREFIX_MAP) -MMD -MP \
	$(shell pkg-config --cflags OpenImageIO 2>/dev/null) \
	$(shell pkg-config --cflags polyclipping freetype2 harfbuzz fontconfig 2>/dev/null) \
	$(CAIRO_CFLAGS) $(MESH_IMPORT_CFLAGS)
# cairo draws the PDF export (src/io/pdf.cpp); -lcairo when its .pc is missing.
CAIRO_CFLAGS := $(shell pkg-config --cflags cairo 2>/dev/null)
CAIRO_LIBS := $(or $(shell pkg-config --libs cairo 2>/dev/null),-lcairo)
# AMF (libxml2, libzip) and 3MF (lib3mf 1.8, whose .pc is named lib3MF)
# import; -l3MF when its .pc is missing.
MESH_IMPORT_CFLAGS := $(shell pkg-config --cflags libxml-2.0 libzip 2>/dev/null) \
	$(or $(shell pkg-config --cflags lib3MF 2>/dev/null),-I/usr/include/lib3mf)
MESH_IMPORT_LIBS := $(or $(shell pkg-config --libs libxml-2.0 2>/dev/null),-lxml2) \
	$(or $(shell pkg-config --libs lib3MF 2>/dev/null),-l3MF -lzip -lz) \
	$(or $(shell pkg-config --libs libzip 2>/dev/null),-lzip)
# json-c reads customizer parameter files (-p, src/cli/params.c): the
# command's, not the library's.
JSON_CFLAGS := $(shell pkg-config --cflags json-c 2>/dev/null)
# The viewer's window and input (src/cli/viewer.c only).
SDL_CFLAGS := $(or $(shell pkg-config --cflags sdl2 SDL2_ttf fontconfig 2>/dev/null),-I/usr/include/SDL2)
SDL_LIBS := $(or $(shell pkg-config --libs sdl2 SDL2_ttf fontconfig 2>/dev/null),-lSDL2_ttf -lSDL2 -lfontconfig)
JSON_LIBS := $(or $(shell pkg-config --libs json-c 2>/dev/null),-ljson-c)
# OpenImageIO is not linked: the image adapter loads it (IMAGE_SO below).
OIIO_LIBS = $(shell pkg-config --libs OpenImageIO 2>/dev/null)
LDLIBS   = -lOpenMeshCore \
	$(shell pkg-config --libs polyclipping freetype2 harfbuzz fontconfig 2>/dev/null) \
	$(CAIRO_LIBS) $(MESH_IMPORT_LIBS) \
	-lpthread -lm

# What building rayscad (and rendering the demo) needs, and what the tests
# add: the peers they compare against, Criterion, Xvfb, the sanitizer
# toolchain.  make demo installs the first only.
BUILD_DEBS = pkg-config g++ make libopenimageio-dev libopenmesh-dev \
	libpolyclipping-dev libfreetype-dev libharfbuzz-dev libfontconfig-dev fonts-liberation \
	libxml2-dev libzip-dev lib3mf-dev libjson-c-dev libcairo2-dev libsdl2-dev \
	libsdl2-ttf-dev
TEST_DEBS = openscad xvfb xauth povray openimageio-tools libcriterion-dev \
	clang libclang-rt-dev man-db poppler-utils xdotool x11-apps
DEBS = $(BUILD_DEBS) $(TEST_DEBS)

LIB_SRC  = $(wildcard src/intervals/*.c src/csg/*.c src/geom/*.c src/scad/*.c src/scad/builtins/*.c \
	src/rayscad/*.c \
	src/render/*.c src/mesh/*.c \
	src/io/*.c)
IO_SRC   = $(filter-out src/io/image.cpp,$(wildcard src/io/*.cpp))
CLI_SRC  = $(wildcard src/cli/*.c)
TEST_SRC = $(wildcard tests/*/test_*.c)
TOOL_SRC = $(wildcard tests/tools/*.c)

LIB_OBJ  = $(LIB_SRC:%.c=$(BUILD)/obj/%.o) $(IO_SRC:%.cpp=$(BUILD)/obj/%.o)
CLI_OBJ  = $(CLI_SRC:%.c=$(BUILD)/obj/%.o)
VERSION  = $(shell sed -n 's/^\#define RAYSCAD_VERSION_STRING "\(.*\)"/\1/p' include/rayscad.h)
MAJOR    = $(firstword $(subst ., ,$(VERSION)))
SO_NAME  = librayscad.so.$(VERSION)
LIB_PIC  = $(LIB_SRC:%.c=$(BUILD)/pic/%.o) $(IO_SRC:%.cpp=$(BUILD)/pic/%.o)
IMAGE_SO = $(BUILD)/rayscad-image.so
TESTS    = $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
TOOLS    = $(TOOL_SRC:tests/tools/%.c=$(BUILD)/tools/%)

.PHONY: all deps deps-build demo test unit cli viewer compare conformance corpus meshcheck asan clean format bench fuzz hostile \
	valgrind install uninstall installcheck format-check
.DEFAULT_GOAL := all

# The test programs (one folder per module, as tests/ mirrors src/) and the
# tools find the image adapter through a link in their folder.
ADAPTER_LINKS = $(addsuffix $(notdir $(IMAGE_SO)),$(sort $(dir $(TESTS) $(TOOLS))))

all: $(BUILD)/rayscad $(BUILD)/$(SO_NAME) $(TESTS) $(TOOLS) $(ADAPTER_LINKS)

$(BUILD)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -c $< -o $@

$(BUILD)/obj/%.o: %.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -c $< -o $@

# The OpenImageIO adapter: image.cpp and the temp-file helpers as a shared
# object of their own, found beside the program or library (or in
# lib/rayscad/ when installed) and dlopened only when an image is read or
# written (src/io/image_loader.c says why).
$(ADAPTER_LINKS): $(IMAGE_SO)
	@mkdir -p $(dir $@)
	ln -sf $(abspath $(IMAGE_SO)) $@

$(BUILD)/pic/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -fPIC -c $< -o $@

$(BUILD)/pic/%.o: %.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -fPIC -c $< -o $@

$(IMAGE_SO): $(BUILD)/pic/src/io/image.o $(BUILD)/pic/src/io/temp_file.o
	$(CXX) $(SANFLAGS) -shared -Wl,--as-needed -o $@ $^ $(OIIO_LIBS)

# The adapter's libraries in reverse load order, leaves first, for the
# loader to open one by one before the adapter (image_loader.c says why).
# Only a speed-up: an empty list (no ldd) loads the same, more slowly.
# Sanitizer builds go without: in that load order LeakSanitizer's exit scan
# of dynamic TLS follows a bogus block and dies ("Tracer caught signal 11",
# two of compare's models, every run) while the plain build runs clean,
# valgrind included.
IMAGE_DEPS = $(BUILD)/rayscad-image.deps
IMAGE_DEPS_FLAG = $(if $(filter 1,$(SAN)),,-DRAYSCAD_IMAGE_DEPS='"$(abspath $(IMAGE_DEPS))"')

$(IMAGE_DEPS): $(IMAGE_SO)
	(ldd $< 2>/dev/null || true) | awk '$$2 == "=>" && $$3 ~ /^\/[^"\\]*$$/ {print $$3}' \
		| tac > $@.tmp && mv $@.tmp $@

$(BUILD)/obj/src/io/image_loader.o: src/io/image_loader.c $(IMAGE_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(IMAGE_DEPS_FLAG) -c $< -o $@

$(BUILD)/pic/src/io/image_loader.o: src/io/image_loader.c $(IMAGE_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -fPIC $(IMAGE_DEPS_FLAG) -c $< -o $@

$(BUILD)/librayscad.a: $(LIB_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	ar rcs $@ $^

# The shared library exports include/rayscad.h's functions and nothing
# else (the version script lists them, taken from the header); its soname
# carries the major version.

$(BUILD)/exports.map: include/rayscad.h
	@mkdir -p $(dir $@)
	(echo '{ global:'; sed -n 's/^.*[ *]\(rayscad_[a-z_]*\)(.*/    \1;/p' $< | sort -u; \
		echo 'local: *; };') > $@

$(BUILD)/$(SO_NAME): $(LIB_PIC) $(BUILD)/exports.map
	$(CXX) $(SANFLAGS) -shared -Wl,-soname,librayscad.so.$(MAJOR) \
		-Wl,--version-script=$(BUILD)/exports.map -o $@ $(LIB_PIC) $(LDLIBS)
	ln -sf $(SO_NAME) $(BUILD)/librayscad.so.$(MAJOR)
	ln -sf $(SO_NAME) $(BUILD)/librayscad.so

$(BUILD)/rayscad: $(CLI_OBJ) $(BUILD)/librayscad.a
	$(CXX) $(SANFLAGS) -o $@ $^ $(LDLIBS) $(JSON_LIBS) $(SDL_LIBS)

$(BUILD)/obj/src/cli/viewer.o $(BUILD)/obj/src/cli/viewer_text.o: CFLAGS += $(SDL_CFLAGS)

$(BUILD)/obj/src/cli/params.o: CFLAGS += $(JSON_CFLAGS)

# tests/cli/test_params.c tests src/cli/params.c, which is not in the library.
$(BUILD)/tests/cli/test_params: $(BUILD)/obj/src/cli/params.o
$(BUILD)/tests/cli/test_params: LDLIBS += $(JSON_LIBS)

$(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $(BUILD)/librayscad.a
	@mkdir -p $(dir $@)
	$(CXX) $(SANFLAGS) -o $@ $^ -lcriterion $(LDLIBS)

$(BUILD)/tools/%: $(BUILD)/obj/tests/tools/%.o $(BUILD)/librayscad.a
	@mkdir -p $(dir $@)
	$(CXX) $(SANFLAGS) -o $@ $^ $(LDLIBS)

# ---- installation ----------------------------------------------------------------
# make install [PREFIX=/usr/local] [DESTDIR=…]: the command, the static and
# shared library, the header, pkg-config's rayscad.pc, the image adapter in
# lib/rayscad/ (found from the program or the library, wherever PREFIX is)
# the man page and bash's completion.  make uninstall takes them away again.
PREFIX ?= /usr/local
BINDIR  = $(PREFIX)/bin
LIBDIR  = $(PREFIX)/lib
INCDIR  = $(PREFIX)/include
MANDIR  = $(PREFIX)/share/man/man1
COMPDIR = $(PREFIX)/share/bash-completion/completions
PCDIR   = $(LIBDIR)/pkgconfig

$(BUILD)/rayscad.pc: Makefile include/rayscad.h
	@mkdir -p $(dir $@)
	printf '%s\n' 'prefix=$(PREFIX)' 'exec_prefix=$${prefix}' 'libdir=$${exec_prefix}/lib' \
		'includedir=$${prefix}/include' '' 'Name: rayscad' \
		'Description: OpenSCAD files rendered, meshed and measured by ray casting with interval lists' \
		'Version: $(VERSION)' 'Cflags: -I$${includedir}' 'Libs: -L$${libdir} -lrayscad' \
		'Libs.private: $(strip $(LDLIBS)) -lstdc++' > $@

install: $(BUILD)/rayscad $(BUILD)/$(SO_NAME) $(BUILD)/librayscad.a $(IMAGE_SO) $(BUILD)/rayscad.pc
	install -d $(DESTDIR)$(BINDIR) $(DESTDIR)$(LIBDIR)/rayscad $(DESTDIR)$(INCDIR) \
		$(DESTDIR)$(MANDIR) $(DESTDIR)$(PCDIR) $(DESTDIR)$(COMPDIR)
	install -m 755 $(BUILD)/rayscad $(DESTDIR)$(BINDIR)/rayscad
	install -m 755 $(BUILD)/$(SO_NAME) $(DESTDIR)$(LIBDIR)/$(SO_NAME)
	ln -sf $(SO_NAME) $(DESTDIR)$(LIBDIR)/librayscad.so.$(MAJOR)
	ln -sf $(SO_NAME) $(DESTDIR)$(LIBDIR)/librayscad.so
	install -m 644 $(BUILD)/librayscad.a $(DESTDIR)$(LIBDIR)/librayscad.a
	install -m 755 $(IMAGE_SO) $(DESTDIR)$(LIBDIR)/rayscad/$(notdir $(IMAGE_SO))
	install -m 644 include/rayscad.h $(DESTDIR)$(INCDIR)/rayscad.h
	install -m 644 docs/rayscad.1 $(DESTDIR)$(MANDIR)/rayscad.1
	install -m 644 docs/rayscad.bash-completion $(DESTDIR)$(COMPDIR)/rayscad
	install -m 644 $(BUILD)/rayscad.pc $(DESTDIR)$(PCDIR)/rayscad.pc

uninstall:
	rm -f $(DESTDIR)$(BINDIR)/rayscad $(DESTDIR)$(LIBDIR)/$(SO_NAME) \
		$(DESTDIR)$(LIBDIR)/librayscad.so.$(MAJOR) $(DESTDIR)$(LIBDIR)/librayscad.so \
		$(DESTDIR)$(LIBDIR)/librayscad.a $(DESTDIR)$(LIBDIR)/rayscad/$(notdir $(IMAGE_SO)) \
		$(DESTDIR)$(INCDIR)/rayscad.h $(DESTDIR)$(MANDIR)/rayscad.1 $(DESTDIR)$(PCDIR)/rayscad.pc \
		$(DESTDIR)$(COMPDIR)/rayscad
	-rmdir $(DESTDIR)$(LIBDIR)/rayscad 2>/dev/null

# An installation into a scratch DESTDIR, used as a stranger would use it
# (tests/rayscad/install_test.sh).
installcheck: all
	tests/rayscad/install_test.sh $(BUILD)

# Install the Debian packages of $(1) that are missing.
define install_debs
	@missing=""; for p in $(1); do \
		dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
		echo "installing:$$missing"; \
		apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing >/dev/null; \
	fi
endef

deps:
	$(call install_debs,$(DEBS))

deps-build:
	$(call install_debs,$(BUILD_DEBS))

demo: deps-build
	$(MAKE) $(BUILD)/rayscad
	@mkdir -p out
	$(BUILD)/rayscad models/demo.scad -o out/demo.png --samples 3 \
		$$(sed -n 's|^// args: *||p' models/demo.scad)
	@echo "wrote out/demo.png"

# Criterion workers per test binary.  The sanitizer run uses one: with two,
# Criterion's own runner (the parent process, which runs no test code)
# leaks a 48-byte calloc at exit that LeakSanitizer reports (test_scad,
# every run), and a suppression matching libcriterion would also hide leaks
# in our code, whose stacks pass through it.
UNIT_JOBS ?= $(if $(filter 1,$(SAN)),1,2)

unit: all
	@fail=0; for t in $(TESTS); do $$t --jobs=$(UNIT_JOBS) || fail=1; done; exit $$fail

cli: all
	tests/cli/cli_test.sh $(BUILD)
	tests/cli/openscad_flags.sh $(BUILD)
	tests/cli/params_test.sh $(BUILD)
	tests/cli/colors_test.py $(BUILD)

# The viewer in a real window under Xvfb, driven by xdotool (tests/viewer_test.sh).
viewer: all
	tests/viewer_test.sh $(BUILD)

# Against the real openscad: rendered masks (tests/cli/compare_openscad.sh),
# --measure on random faceted CSG against the volume and area of openscad's STL
# (tests/cli/measure_openscad.py), and the same scenes' meshes, closed and
# nine in ten the exact boundary of their booleans (tests/cli/mesh_exact_openscad.py).
compare: all
	tests/cli/compare_openscad.sh $(BUILD)
	tests/cli/measure_openscad.py $(BUILD)
	tests/cli/mesh_exact_openscad.py $(BUILD)

# Hostile inputs and OpenSCAD's examples: no signal, no hang, no sanitizer report,
# no output left behind by a failure (tests/cli/hostile.sh).
hostile: all
	tests/cli/hostile.sh $(BUILD)

# The demos under valgrind memcheck (minutes; not part of make test).
valgrind: all
	tests/cli/valgrind.sh $(BUILD)

conformance: all
	tests/cli/conformance.sh $(BUILD)

# Real OpenSCAD code against openscad 2021.01: the regression corpus (.echo,
# .csg, .png silhouettes, .stl volumes) and BOSL2's test scripts (.echo) of ../shared/corpora,
# where present (tests/cli/corpus.py; about 20 minutes on 2 cores, openscad's
# outputs kept in BUILD/corpus/ref).  CORPUS_UPDATE=1 rewrites tests/corpus/passing.txt.
corpus: all
	python3 tests/cli/corpus.py $(BUILD) $(if $(CORPUS_UPDATE),--update)

meshcheck: all
	tests/cli/mesh_compare.sh $(BUILD)

test: deps
	$(MAKE) format-check
	$(MAKE) all
	$(MAKE) unit
	$(MAKE) cli
	$(MAKE) viewer
	$(MAKE) conformance
	$(MAKE) meshcheck
	$(MAKE) compare
	$(MAKE) hostile
	$(MAKE) installcheck

asan: deps
	$(MAKE) BUILD=build-asan SAN=1 OPT="-O1 -g" all
	$(MAKE) BUILD=build-asan SAN=1 OPT="-O1 -g" unit
	$(MAKE) BUILD=build-asan SAN=1 OPT="-O1 -g" cli
	$(MAKE) BUILD=build-asan SAN=1 OPT="-O1 -g" conformance
	$(MAKE) BUILD=build-asan SAN=1 OPT="-O1 -g" meshcheck
	$(MAKE) BUILD=build-asan SAN=1 OPT="-O1 -g" compare
	$(MAKE) BUILD=build-asan SAN=1 OPT="-O1 -g" hostile

# Benchmarks against povray, openscad and manifold-3d (not a test; bench/run.py).
bench: deps
	$(MAKE) all
	@test -d bench/node_modules/manifold-3d || (cd bench && npm install --no-audit --no-fund) || \
		echo "bench: npm install failed; meshing runs without manifold-3d"
	python3 bench/run.py $(BUILD)

# libFuzzer harnesses (tests/fuzz/): the library built with clang, ASan, UBSan
# and fuzzer coverage into build-fuzz/ (no image I/O: the harnesses write no
# files); `make fuzz SECONDS=N` runs each harness
# for N seconds (default 60), one after the other, seeded from tests/ and
# models/, and writes what it finds to build-fuzz/findings/.
SECONDS ?= 60
FUZZ      = build-fuzz
FUZZ_SAN  = -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
FUZZ_NAMES = parse eval pipeline
FUZZ_BINS = $(FUZZ_NAMES:%=$(FUZZ)/fuzz_%)
FUZZ_C    = $(LIB_SRC)
FUZZ_OBJ  = $(FUZZ_C:%.c=$(FUZZ)/obj/%.o) $(IO_SRC:%.cpp=$(FUZZ)/obj/%.o)
.PRECIOUS: $(FUZZ)/obj/%.o

$(FUZZ)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	clang -std=c11 -D_POSIX_C_SOURCE=200809L -O1 -g $(FUZZ_SAN) -fsanitize=fuzzer-no-link -MMD -MP \
		$(shell pkg-config --cflags libxml-2.0 2>/dev/null) -c $< -o $@

$(FUZZ)/obj/%.o: %.cpp
	@mkdir -p $(dir $@)
	clang++ -std=c++17 -O1 -g $(FUZZ_SAN) -fsanitize=fuzzer-no-link -MMD -MP \
		$(shell pkg-config --cflags OpenImageIO polyclipping freetype2 harfbuzz fontconfig 2>/dev/null) \
		$(CAIRO_CFLAGS) -c $< -o $@

$(FUZZ)/fuzz_%: $(FUZZ)/obj/tests/fuzz/fuzz_%.o $(FUZZ_OBJ)
	clang++ $(FUZZ_SAN) -fsanitize=fuzzer -o $@ $^ $(LDLIBS)

fuzz: $(FUZZ_BINS)
	@mkdir -p $(FUZZ)/findings
	@for f in $(FUZZ_NAMES); do \
		mkdir -p $(FUZZ)/corpus/$$f; \
		echo "fuzz_$$f: $(SECONDS) s"; \
		$(FUZZ)/fuzz_$$f -max_total_time=$(SECONDS) -timeout=20 -rss_limit_mb=2560 -max_len=4096 \
			-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
			-dict=tests/fuzz/scad.dict -artifact_prefix=$(FUZZ)/findings/$$f- \
			$(FUZZ)/corpus/$$f tests/fuzz/corpus tests/hostile tests/lang tests/models models \
			> $(FUZZ)/fuzz_$$f.log 2>&1; \
		tail -n 2 $(FUZZ)/fuzz_$$f.log; \
	done
	@if ls $(FUZZ)/findings | grep -q .; then echo "findings:"; ls $(FUZZ)/findings; exit 1; fi

# Every C, C++ and header file of ours, as .clang-format lays it out:
# `make format` rewrites them, `make format-check` (part of make test, so
# of CI) fails on any that differs.
FORMATTED = $(sort $(shell find src tests include examples -name '*.c' -o -name '*.h' -o \
	-name '*.cpp'))

format:
	clang-format -i $(FORMATTED)

format-check:
	clang-format --dry-run -Werror $(FORMATTED)

clean:
	rm -rf build build-asan build-fuzz out

-include $(shell find $(BUILD) $(if $(filter fuzz $(FUZZ)/%,$(MAKECMDGOALS)),$(FUZZ)) -name '*.d' 2>/dev/null)
