# dtdel -- vertex deletion for 3D Delaunay triangulations, checked against CGAL.
#
#   make              build/dtdel (CLI), build/libdtdel.so and build/libdtdel.a
#   make deps         install the Debian packages (or say what to install)
#   make test         release and sanitizer (ASan+UBSan) test suites
#   make bench        the full benchmark, tables and plots into results/
#   make bench-quick  a short benchmark (about 2 minutes) into results/quick/
#   make plots        redraw the plots from results/*.csv
#   make install      PREFIX=/usr/local [DESTDIR=]: libraries, headers,
#                     dtdel.pc, the CLI and the Python package
#   make python       the Python package in place: python/dtdel
#   make clean
#
# Three builds share the sources: build/ (release, -O2), build/asan/
# (sanitizers, -O1 -g, validator after every operation in tests) and
# build/count/ (release with counters compiled in, for counting runs);
# build/tsan/ (ThreadSanitizer) builds the threaded tests alone.

PREFIX  ?= /usr/local
CC      ?= gcc
CXX     ?= g++
WARN     = -Wall -Wextra -Wshadow -Wconversion -Wno-sign-conversion -Wstrict-prototypes -Wmissing-prototypes
CSTD     = -std=c11 -D_POSIX_C_SOURCE=200809L -Isrc -I.
# -ffp-contract=off: the predicate filters' error bounds assume no FMA fusion
# (src/geom/fp.h makes the sources refuse it too; build/contract/ checks).
# -O3 for our engine and for the CGAL shim alike (CGAL's own CMake Release
# default), so the bench compares like with like.
OPT      = -O3 -DNDEBUG -ffp-contract=off
# Position-independent, so that the objects make the shared library and a
# static archive that can go into one; -fvisibility=hidden exports only
# what dtdel.h and dtdel_stats.h declare (DD_API_BEGIN), and lets the
# library's internal calls bind locally, as -fPIE's do.
PIC      = -fPIC -fvisibility=hidden
CFLAGS_R = $(CSTD) $(WARN) $(OPT) $(PIC)
# float-cast-overflow: a NaN or out-of-range double converted to an
# integer (gcc's "undefined" leaves it out; clang's, in make fuzz, not).
CFLAGS_A = $(CSTD) $(WARN) -O1 -g -ffp-contract=off -fsanitize=address,undefined,float-cast-overflow -fno-omit-frame-pointer -DDD_TEST_BUILD
CFLAGS_C = $(CFLAGS_R) -DDD_COUNTERS
CXXFLAGS_R = -std=c++17 -O3 -DNDEBUG -frounding-math -Wall -Wextra
# The sanitizer and counting builds link the release object of the CGAL
# shim: CGAL is not ours to instrument, and compiling it once saves
# minutes.  CXXFLAGS_A only links the sanitizer runtime in.
CXXFLAGS_A = -std=c++17 -O1 -fsanitize=address,undefined
LIBS     = -lgmp -lmpfr -lm -ltbb -ltbbmalloc -pthread
# What the library itself needs (the CLI and tests add CGAL's MPFR).
LIB_LIBS = -lgmp -lm -pthread

# The version, read from its one source, dtdel.h.
version_part = $(shell sed -n 's/^\#define DD_VERSION_$(1) *\([0-9][0-9]*\).*/\1/p' src/dtdel.h)
VERSION  := $(call version_part,MAJOR).$(call version_part,MINOR).$(call version_part,PATCH)
SONAME   := libdtdel.so.$(call version_part,MAJOR)

# The engine's layers, bottom up (docs/architecture.md): each folder of
# src/ uses only those before it; variants/ and src/api/ sit on top.
LAYERS   = geom mesh delete wrap
LIB_SRC  = $(foreach l,$(LAYERS),$(wildcard src/$(l)/*.c)) $(wildcard variants/*.c) $(wildcard src/api/*.c)
# The command's layers, above them, bottom up: src/tool (what both halves
# share), src/bench (the benchmark harness), src/cli (the user's commands
# and the command table); build/dtdel links all three.
CLI_LAYERS = tool bench cli
CLI_SRC  = $(foreach l,$(CLI_LAYERS),$(wildcard src/$(l)/*.c))
DATA_SRC = $(wildcard datasets/*.c)
SHIM_SRC = $(wildcard src/cgal/*.cpp)
# The CGAL reference objects, compiled once in the release build (see below).
SHIM_OBJ = $(SHIM_SRC:%.cpp=$(B)/obj/%.o)
TEST_C   = $(wildcard tests/test_*.c)
HDRS     = $(wildcard src/*.h) $(wildcard src/*/*.h) $(wildcard variants/*.h) src/cgal/cgal_shim.h src/cgal/cgal_query.h src/cgal/cgal_refine.h src/cgal/cgal_par.h $(wildcard datasets/*.h)

B = build
A = build/asan
K = build/count
# The contract build: the library as a user might compile it into their
# own project, GNU C with contraction allowed and every extension of the
# CPU, and the tests that certify its signs (src/geom/fp.h): every
# filter path against exact signs, and edits (deletions, insertions,
# moves through the lifted filter) against CGAL; test_delete's full
# course coverage runs in the other builds, within make test's time.
C = build/contract
CFLAGS_CT = -std=gnu11 -D_POSIX_C_SOURCE=200809L -Isrc -I. $(WARN) -O3 -march=native -ffp-contract=fast -DDD_TEST_BUILD
LIB_OBJ_CT = $(LIB_SRC:%.c=$(C)/obj/%.o)
TESTS_CT = $(C)/tests/test_filters $(C)/tests/test_access $(C)/tests/test_move

LIB_OBJ_R = $(LIB_SRC:%.c=$(B)/obj/%.o)
LIB_OBJ_A = $(LIB_SRC:%.c=$(A)/obj/%.o)
LIB_OBJ_K = $(LIB_SRC:%.c=$(K)/obj/%.o)
DATA_OBJ_B = $(DATA_SRC:%.c=$(B)/obj/%.o)
DATA_OBJ_A = $(DATA_SRC:%.c=$(A)/obj/%.o)
DATA_OBJ_K = $(DATA_SRC:%.c=$(K)/obj/%.o)

TESTS_R = $(TEST_C:tests/%.c=$(B)/tests/%)
TESTS_A = $(TEST_C:tests/%.c=$(A)/tests/%)

.PHONY: all deps test test-release test-asan bench bench-quick plots install clean print-goals \
	print-cflags-contract print-cflags-release
.DEFAULT_GOAL := all

all: deps $(B)/dtdel $(B)/libdtdel.a $(B)/libdtdel.so $(B)/dtdel.pc

# Every compile waits for the Debian packages: it has the stamp that
# `make deps` writes as an order-only prerequisite, so `make -jN` on a
# fresh machine compiles nothing before CGAL's headers are there.  The
# stamp is remade when the package list (scripts/deps.sh) changes.
DEPS_STAMP = build/.deps-stamp
deps: $(DEPS_STAMP)
$(DEPS_STAMP): scripts/deps.sh
	@sh scripts/deps.sh
	@mkdir -p $(dir $@) && touch $@

# ---- release ----------------------------------------------------------------
$(B)/obj/%.o: %.c $(HDRS) | $(DEPS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_R) -c $< -o $@
$(B)/obj/%.o: %.cpp $(HDRS) | $(DEPS_STAMP)
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS_R) -c $< -o $@
# The installed static archive: one object, linked partially, whose
# hidden (internal) names are made local, so that it defines only the
# public names, as the shared library exports them.
$(B)/libdtdel.a: $(LIB_OBJ_R) | $(DEPS_STAMP)
	@rm -f $@ $(B)/obj/libdtdel.o
	$(LD) -r -o $(B)/obj/libdtdel.o $^
	objcopy --localize-hidden $(B)/obj/libdtdel.o
	ar rcs $@ $(B)/obj/libdtdel.o
# The tests' archive: every object, internal names included (tests call
# the layers directly); never installed.
$(B)/libdtdel-internal.a: $(LIB_OBJ_R) | $(DEPS_STAMP)
	@rm -f $@
	ar rcs $@ $^
$(B)/libdtdel.so.$(VERSION): $(LIB_OBJ_R) | $(DEPS_STAMP)
	$(CC) -shared -Wl,-soname,$(SONAME) -Wl,-z,defs $^ -o $@ $(LIB_LIBS)
$(B)/libdtdel.so: $(B)/libdtdel.so.$(VERSION) | $(DEPS_STAMP)
	ln -sf libdtdel.so.$(VERSION) $(B)/$(SONAME)
	ln -sf $(SONAME) $@
# pkg-config's file for PREFIX (make install writes its own for its PREFIX)
MAKE_PC = sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(VERSION)|' -e 's|@LIBS_PRIVATE@|$(LIB_LIBS)|' dtdel.pc.in
$(B)/dtdel.pc: dtdel.pc.in src/dtdel.h | $(DEPS_STAMP)
	$(MAKE_PC) >$@
# The CLI uses only the public calls: it links the installed archive.
$(B)/dtdel: $(CLI_SRC:%.c=$(B)/obj/%.o) $(DATA_OBJ_B) $(SHIM_OBJ) $(B)/libdtdel.a | $(DEPS_STAMP)
	$(CXX) $(CXXFLAGS_R) $^ -o $@ $(LIBS)
$(B)/tests/%: tests/%.c $(DATA_OBJ_B) $(SHIM_OBJ) $(B)/libdtdel-internal.a tests/testlib.h tests/testcgal.h | $(DEPS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_R) -c $< -o $@.o
	$(CXX) $(CXXFLAGS_R) $@.o $(DATA_OBJ_B) $(SHIM_OBJ) $(B)/libdtdel-internal.a -o $@ $(LIBS)

# ---- sanitizers ---------------------------------------------------------------
$(A)/obj/%.o: %.c $(HDRS) | $(DEPS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_A) -c $< -o $@
$(A)/libdtdel.a: $(LIB_OBJ_A) | $(DEPS_STAMP)
	@rm -f $@
	ar rcs $@ $^
$(A)/dtdel: $(CLI_SRC:%.c=$(A)/obj/%.o) $(DATA_OBJ_A) $(SHIM_OBJ) $(A)/libdtdel.a | $(DEPS_STAMP)
	$(CXX) $(CXXFLAGS_A) $^ -o $@ $(LIBS)
$(A)/tests/%: tests/%.c $(DATA_OBJ_A) $(SHIM_OBJ) $(A)/libdtdel.a tests/testlib.h tests/testcgal.h | $(DEPS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_A) -c $< -o $@.o
	$(CXX) $(CXXFLAGS_A) $@.o $(DATA_OBJ_A) $(SHIM_OBJ) $(A)/libdtdel.a -o $@ $(LIBS)

# ---- thread sanitizer: the threaded tests (concurrent reads, parallel builds) -
T = build/tsan
# -Wno-maybe-uninitialized: gcc 12 at -O1 under -fsanitize=thread warns
# falsely about src/wrap/scan.c (the other builds do not).
CFLAGS_T = $(CSTD) $(WARN) -Wno-maybe-uninitialized -O1 -g -ffp-contract=off -fsanitize=thread -DDD_TEST_BUILD
LIB_OBJ_T = $(LIB_SRC:%.c=$(T)/obj/%.o)
DATA_OBJ_T = $(DATA_SRC:%.c=$(T)/obj/%.o)
$(T)/obj/%.o: %.c $(HDRS) | $(DEPS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_T) -c $< -o $@
$(T)/libdtdel.a: $(LIB_OBJ_T) | $(DEPS_STAMP)
	@rm -f $@
	ar rcs $@ $^
$(T)/tests/test_threads $(T)/tests/test_parallel: $(T)/tests/%: tests/%.c $(DATA_OBJ_T) $(T)/libdtdel.a tests/testlib.h tests/testcgal.h | $(DEPS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_T) -pthread $< $(DATA_OBJ_T) $(T)/libdtdel.a -o $@ $(LIBS)
$(B)/tests/test_threads $(A)/tests/test_threads: LIBS += -pthread

# ---- contract build (src/geom/fp.h) -------------------------------------------
$(C)/obj/%.o: %.c $(HDRS) | $(DEPS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_CT) -c $< -o $@
$(C)/libdtdel.a: $(LIB_OBJ_CT) | $(DEPS_STAMP)
	@rm -f $@
	ar rcs $@ $^
$(C)/tests/%: tests/%.c $(DATA_OBJ_B) $(SHIM_OBJ) $(C)/libdtdel.a tests/testlib.h tests/testcgal.h | $(DEPS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_CT) -c $< -o $@.o
	$(CXX) $(CXXFLAGS_R) $@.o $(DATA_OBJ_B) $(SHIM_OBJ) $(C)/libdtdel.a -o $@ $(LIBS)

# ---- counting build -----------------------------------------------------------
$(K)/obj/%.o: %.c $(HDRS) | $(DEPS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_C) -c $< -o $@
$(K)/libdtdel.a: $(LIB_OBJ_K) | $(DEPS_STAMP)
	@rm -f $@
	ar rcs $@ $^
$(K)/dtdel: $(CLI_SRC:%.c=$(K)/obj/%.o) $(DATA_OBJ_K) $(SHIM_OBJ) $(K)/libdtdel.a | $(DEPS_STAMP)
	$(CXX) $(CXXFLAGS_R) $^ -o $@ $(LIBS)

# ---- bench summary and plots ----------------------------------------------------
# scripts/summarize/: one program, its files compiled together
SUM_SRC = $(sort $(wildcard scripts/summarize/*.c))
SUM_DEPS = $(SUM_SRC) scripts/summarize/summarize.h src/bench/buckets.h
$(B)/summarize: $(SUM_DEPS) | $(DEPS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_R) $(SUM_SRC) -o $@ -lm
$(A)/summarize: $(SUM_DEPS) | $(DEPS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_A) $(SUM_SRC) -o $@ -lm

# ---- tests --------------------------------------------------------------------
# Both suites run, and the threaded test under ThreadSanitizer; the
# runner prints per-test lines and ends with
# "N passed, N failed"; it exits non-zero on any failure.
# The builds run on every processor unless the caller chose -jN.
NPROC := $(shell nproc 2>/dev/null || echo 2)
test: deps
	@$(MAKE) --no-print-directory $(if $(filter -j%,$(MAKEFLAGS)),,-j$(NPROC)) all python $(TESTS_R) $(B)/summarize $(A)/dtdel $(TESTS_A) $(A)/summarize \
		$(T)/tests/test_threads $(T)/tests/test_parallel $(TESTS_CT)
	@sh tests/run.sh $(B) $(A) $(T) $(C)

# The files make test, bench, soak and fuzz build (tests/test_make.sh
# checks that each waits for the deps stamp).
print-goals:
	@echo $(B)/python/.stamp $(B)/dtdel $(B)/libdtdel.a $(B)/libdtdel.so $(B)/dtdel.pc $(B)/tests/soak $(TESTS_R) $(B)/summarize $(A)/dtdel $(TESTS_A) $(A)/summarize $(K)/dtdel $(T)/tests/test_threads $(T)/tests/test_parallel $(TESTS_CT) $(F)/fuzz_readers $(F)/fuzz_ops

# The flags of the contract and release builds (tests/test_fpeval.sh).
print-cflags-contract:
	@echo $(CFLAGS_CT)
print-cflags-release:
	@echo $(CFLAGS_R)

# ---- bench --------------------------------------------------------------------
# BENCH_SCALE=4 make bench: four times as many deletions per case.
BENCH_SCALE ?= 1
bench: deps $(B)/dtdel $(K)/dtdel $(B)/summarize python
	@CFLAGS_USED="$(CFLAGS_R)" sh scripts/bench.sh full $(BENCH_SCALE)

bench-quick: deps $(B)/dtdel $(K)/dtdel $(B)/summarize python
	@CFLAGS_USED="$(CFLAGS_R)" sh scripts/bench.sh quick $(BENCH_SCALE)

plots: $(B)/summarize
	@$(B)/summarize results results/*.csv $(if $(wildcard results/weighted/*.csv),--weighted results/weighted/*.csv) && sh scripts/plots.sh results

# DESTDIR only stages the files: dtdel.pc names PREFIX.
# install-lib: the C side alone (tests/test_install.sh, which runs beside
# the Python tests' own install: two pip builds at once collide).
install: install-lib install-python
install-lib: all
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/include
	install -m 755 $(B)/dtdel $(DESTDIR)$(PREFIX)/bin/dtdel
	install -m 644 $(B)/libdtdel.a $(DESTDIR)$(PREFIX)/lib/libdtdel.a
	install -m 755 $(B)/libdtdel.so.$(VERSION) $(DESTDIR)$(PREFIX)/lib/libdtdel.so.$(VERSION)
	ln -sf libdtdel.so.$(VERSION) $(DESTDIR)$(PREFIX)/lib/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(PREFIX)/lib/libdtdel.so
	$(MAKE_PC) >$(DESTDIR)$(PREFIX)/lib/pkgconfig/dtdel.pc
	chmod 644 $(DESTDIR)$(PREFIX)/lib/pkgconfig/dtdel.pc
	install -m 644 src/dtdel.h src/dtdel_stats.h $(DESTDIR)$(PREFIX)/include/
	install -d $(DESTDIR)$(PREFIX)/include/dtdel
	install -m 644 src/dtdel/types.h src/dtdel/stats_types.h $(DESTDIR)$(PREFIX)/include/dtdel/

# ---- the Python package (python/: meson-python, Cython) ----------------------
# `make python` builds the compiled extension in place, in build/python,
# and copies it beside the package's sources, so that PYTHONPATH=python
# /usr/bin/python3 -c 'import dtdel' works from the top of the tree.
# `make install` installs the package into PREFIX with pip, as a user
# would (PIP_BUILD: pip's own meson build dir, kept so that a second
# install compiles nothing).  The extension compiles the library's
# sources itself (python/meson.build, python/list_sources.py).
PYTHON  ?= /usr/bin/python3
PY_DEPS  = python/meson.build python/pyproject.toml python/list_sources.py $(wildcard python/dtdel/*.py*) $(LIB_SRC) $(HDRS)
PIP_BUILD = $(abspath $(B)/pip)
PIP_INSTALL = $(PYTHON) -m pip install --no-build-isolation --no-index --no-deps --quiet \
	--config-settings=builddir=$(PIP_BUILD)
.PHONY: python install-python install-lib
$(B)/python/.stamp: $(PY_DEPS) | $(DEPS_STAMP)
	@if [ ! -f $(B)/python/build.ninja ]; then rm -rf $(B)/python; \
	    meson setup --buildtype=release $(B)/python python >/dev/null || exit 1; fi
	ninja -C $(B)/python >/dev/null
	cp $(B)/python/_core*.so python/dtdel/
	@touch $@
python: $(B)/python/.stamp
install-python: | $(DEPS_STAMP)
	@# meson-python 0.12 reconfigures any existing build dir: one left
	@# half made (an interrupted install) must go first
	@[ -f $(PIP_BUILD)/meson-private/coredata.dat ] || rm -rf $(PIP_BUILD)
	$(PIP_INSTALL) --prefix=$(PREFIX) $(if $(DESTDIR),--root=$(DESTDIR)) ./python
# ---- end of the Python block ------------------------------------------------

clean:
	rm -rf build python/dtdel/_core*.so python/dtdel/__pycache__

# ---- soak: a million deletions checked against CGAL (not in make test) ------
# and weighted deletions and moves against CGAL's regular triangulation.
# SOAK_SCALE=0.01 make soak runs in a few minutes; the workers (SOAK_JOBS,
# one per core) split the cases and the last line sums them.
SOAK_SCALE ?= 1
SOAK_JOBS  ?= 2
# Two halves, one binary: tests/soak.c (unweighted cases, the workers) and
# tests/soak_weighted.c (regular triangulations), sharing tests/soak.h.
SOAK_SRC = tests/soak.c tests/soak_weighted.c
$(B)/tests/soak: $(SOAK_SRC) tests/soak.h tests/testweighted.h tests/fuzz/canon.h $(DATA_OBJ_B) $(SHIM_OBJ) $(B)/libdtdel-internal.a tests/testlib.h | $(DEPS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_R) -c tests/soak.c -o $@.o
	$(CC) $(CFLAGS_R) -c tests/soak_weighted.c -o $@-weighted.o
	$(CXX) $(CXXFLAGS_R) $@.o $@-weighted.o $(DATA_OBJ_B) $(SHIM_OBJ) $(B)/libdtdel-internal.a -o $@ $(LIBS)
.PHONY: soak
soak: deps $(B)/tests/soak
	@$(B)/tests/soak --jobs $(SOAK_JOBS) --scale $(SOAK_SCALE)

# ---- fuzz: libFuzzer targets (clang; not in make test) ----------------------
# FUZZ_SECONDS=60 make fuzz.  scripts/fuzz.sh installs clang and its fuzzer
# runtime with apt-get when they are missing, runs the two targets side by
# side for FUZZ_SECONDS, prints "fuzz: E executions, C crashes" and copies
# each crash into tests/fuzz-corpus/, which test_fuzz_replay replays in
# make test (commit them).
FUZZ_SECONDS ?= 300
FUZZ_CC  ?= clang
F = build/fuzz
CFLAGS_F = $(CSTD) -g -O1 -ffp-contract=off -fsanitize=address,undefined,fuzzer-no-link -fno-sanitize-recover=undefined -fno-omit-frame-pointer -DDD_TEST_BUILD
LIB_OBJ_F  = $(LIB_SRC:%.c=$(F)/obj/%.o)
DATA_OBJ_F = $(DATA_SRC:%.c=$(F)/obj/%.o)
.PHONY: fuzz fuzz-build
# The engine's objects: optimised, and without the comparison tracing that
# guides the fuzzer through parsers: the interpreter runs about 3x faster.
$(LIB_OBJ_F): FUZZ_LIB_FLAGS = -O2 -fno-sanitize-coverage=trace-cmp
$(F)/obj/%.o: %.c $(HDRS) | $(DEPS_STAMP)
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(CFLAGS_F) $(FUZZ_LIB_FLAGS) -c $< -o $@
$(F)/fuzz_%: tests/fuzz/fuzz_%.c tests/fuzz/fuzz_entry.h tests/fuzz/canon.h $(LIB_OBJ_F) $(DATA_OBJ_F) | $(DEPS_STAMP)
	$(FUZZ_CC) $(CFLAGS_F) -fsanitize=fuzzer $< $(LIB_OBJ_F) $(DATA_OBJ_F) -o $@ $(LIBS)
fuzz-build: $(F)/fuzz_readers $(F)/fuzz_ops
fuzz:
	@FUZZ_SECONDS=$(FUZZ_SECONDS) FUZZ_CC=$(FUZZ_CC) sh scripts/fuzz.sh
# the replay test includes the fuzz targets' entry points
$(B)/tests/test_fuzz_replay $(A)/tests/test_fuzz_replay: tests/fuzz/fuzz_entry.h tests/fuzz/canon.h
