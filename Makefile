# SPDX-License-Identifier: GPL-3.0-or-later
# cable: elastic cable knots and links by numerical continuation.
# One hand-written makefile: settings, then rules.  `make help` lists the targets.

CC      ?= gcc
MODE    ?= release
# The Debian interpreter (another python3 without Debian's numpy may come first on PATH)
PYTHON  ?= /usr/bin/python3
BUILD   := build/$(MODE)

# Layers, lowest first (doc/api.md has the picture).  Each folder is
# compiled with the public headers (include/) and the folders of its own and
# lower layers only, so an upward #include does not compile
# (tests/test_layers.c checks the sources too).  continuation/base is the
# ground floor every layer may use; the command line (auto_iface/cli) is a
# program over the library, the Python extension (auto_iface/python) sees the
# public headers only: neither is part of libcable.
LIB_LAYERS := continuation/base continuation equations bc graphics \
              auto_iface/files auto_iface/autoeq auto_iface/session
LAYERS  := $(LIB_LAYERS) auto_iface/cli
WARN    := -Wall -Wextra -Werror -Wshadow -Wpointer-arith -Wcast-align \
           -Wstrict-prototypes -Wmissing-prototypes -Wwrite-strings \
           -Wundef -Wformat=2 -Wvla -Wdouble-promotion -Wnull-dereference
CSTD    := -std=c11 -D_POSIX_C_SOURCE=200809L
SYSINCS := -I/usr/include/suitesparse
PUBINC  := -Iinclude
INCS_continuation/base  := $(PUBINC) -Icontinuation/base
INCS_continuation       := $(INCS_continuation/base) -Icontinuation
INCS_equations          := $(INCS_continuation) -Iequations
INCS_bc                 := $(INCS_equations) -Ibc
INCS_graphics           := $(INCS_bc) -Igraphics
INCS_auto_iface/files   := $(INCS_graphics) -Iauto_iface/files
INCS_auto_iface/autoeq  := $(INCS_auto_iface/files) -Iauto_iface/autoeq
INCS_auto_iface/session := $(INCS_auto_iface/autoeq) -Iauto_iface/session
INCS_auto_iface/cli     := $(INCS_auto_iface/session) -Iauto_iface/cli
INCS_tests              := $(INCS_auto_iface/cli) -Itests
# the folder's include path: the source's folder (tests/: the tests')
layer_incs = $(INCS_$(patsubst %/,%,$(dir $(1)))) $(SYSINCS)
OPT_release := -O2 -g
OPT_asan    := -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all
OPT_fuzz    := -O1 -g -fsanitize=fuzzer-no-link,address,undefined
CFLAGS  := $(CSTD) $(WARN) $(OPT_$(MODE)) -MMD -MP -fPIC $(EXTRA_CFLAGS)
# the library exports only what include/cable/ declares CABLE_API
LIBFLAGS := -fvisibility=hidden
SAN_LD_asan := -fsanitize=address,undefined
LDFLAGS := $(SAN_LD_$(MODE)) $(EXTRA_LDFLAGS)
LIBS_PRE  := -lsundials_kinsol -lsundials_sunlinsolklu -lsundials_sunmatrixsparse \
             -lsundials_nvecserial -lsundials_generic -lklu -lgsl
LIBS_POST := -lcairo -ldl -lpthread -lm
LIBS    := $(LIBS_PRE) -llapacke -llapack -lblas $(LIBS_POST)
# libcable.so and the Python extension carry a private OpenBLAS (static, its
# symbols hidden), set to one thread when loaded (continuation/base/blas_private.c):
# a host's own threaded BLAS (numpy's) then neither slows cable down nor is
# changed by it.  The cable program and the tests use the shared BLAS.
MULTIARCH := $(shell dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || echo x86_64-linux-gnu)
PRIVBLAS_OBJ := $(BUILD)/continuation/base/blas_private.o
LIBS_PRIVBLAS := -Wl,--exclude-libs,liblapacke.a:libopenblas.a $(LIBS_PRE) /usr/lib/$(MULTIARCH)/liblapacke.a \
                 /usr/lib/$(MULTIARCH)/openblas-pthread/libopenblas.a -lgfortran $(LIBS_POST)

PY_SRCS  := $(wildcard auto_iface/python/*.c)
CLI_SRCS := $(wildcard auto_iface/cli/*.c)
CLI_OBJS := $(CLI_SRCS:%.c=$(BUILD)/%.o)
LIB_SRCS := $(filter-out continuation/base/blas_private.c,$(wildcard $(addsuffix /*.c,$(LIB_LAYERS))))
LIB_OBJS := $(LIB_SRCS:%.c=$(BUILD)/%.o)
GEN_OBJS := $(BUILD)/gen/autoeq_compat_text.o
# auto_iface/autoeq/auto_compat: the files cable writes next to an AUTO equation
# file it compiles (auto_iface/autoeq/autoeq_build.c), embedded as C strings
COMPAT_FILES := $(sort $(wildcard auto_iface/autoeq/auto_compat/*))
TEST_SRCS := $(wildcard tests/test_*.c)
TEST_BINS := $(TEST_SRCS:tests/%.c=$(BUILD)/tests/%)
BENCH_SRCS := $(wildcard tests/bench_*.c)
BENCH_BINS := $(BENCH_SRCS:tests/%.c=$(BUILD)/tests/%)
# API tests: the public headers only, linked with libcable.so
API_SRCS := $(wildcard tests/api/api_*.c)
API_BINS := $(API_SRCS:tests/api/api_%.c=$(BUILD)/tests/test_api_%)
PLUGIN_SRCS := $(wildcard tests/plugins/*.c)
PLUGINS  := $(PLUGIN_SRCS:tests/plugins/%.c=$(BUILD)/plugins/%.so)
LIBCABLE := $(BUILD)/libcable.a
LIBSO    := $(BUILD)/libcable.so
# the library's ABI: bumped when exported names or caller-allocated structs
# change (1: the cable_ prefix on every name, cable_session_options.on_error)
SONAME   := libcable.so.1
VERSION  := $(shell sed -n 's/^\#define CABLE_VERSION "\(.*\)"/\1/p' include/cable/cable_version.h)
PREFIX   ?= /usr/local
# Plain `make` only builds: a missing build dependency stops it with the
# Debian package's name and the command that installs it.  The README's
# commands (make demo, make check) and the other targets that run things first
# install every missing package (scripts/install-deps.sh), as `make deps` does.
INSTALL_GOALS := deps demo check valgrind asan doc-img scenes bench bench-atlas stress
DEPS_OK  := $(if $(filter $(INSTALL_GOALS),$(MAKECMDGOALS)),build/.deps-ok,build/.build-deps-ok)

# The Python package: python/cable/*.py and the extension cable._cable
# (auto_iface/python/*.c, the public API only, linked with libcable.a), put
# together in $(BUILD)/python where `cable replay` and the tests find it.
PY_INC   = $(shell $(PYTHON) -c "import sysconfig; print(sysconfig.get_paths()['include'])")
NP_INC   = $(shell $(PYTHON) -c "import numpy; print(numpy.get_include())")
PY_OBJS  := $(PY_SRCS:%.c=$(BUILD)/%.o)
PYPKG    := $(BUILD)/python/cable
PY_FILES := $(patsubst python/cable/%,$(PYPKG)/%,$(wildcard python/cable/*.py))
PY_SO    := $(PYPKG)/_cable.so

.PHONY: doc-img bench-atlas all lib python install check asan valgrind demo scenes bench stress fuzz clean help deps tests-build

all: cable $(LIBSO) python

# Dependencies come from Debian; the script installs only what is missing.
build/.deps-ok: scripts/install-deps.sh
	@bash scripts/install-deps.sh
	@mkdir -p build && touch $@
build/.build-deps-ok: scripts/install-deps.sh
	@bash scripts/install-deps.sh --check-build
	@mkdir -p build && touch $@
deps: build/.deps-ok

$(LIB_OBJS): $(BUILD)/%.o: %.c | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(LIBFLAGS) $(call layer_incs,$<) -c $< -o $@

# The writhe's double sum (equations/ribbon.c): sqrt as one instruction, without
# the errno check (its argument, a squared distance, is never negative)
$(BUILD)/equations/ribbon.o: CFLAGS += -fno-math-errno

# The extension sees the public headers and its own folder only.
$(PY_OBJS): $(BUILD)/%.o: %.c | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(PUBINC) -Iauto_iface/python -isystem $(PY_INC) -isystem $(NP_INC) -c $< -o $@

$(BUILD)/auto_iface/cli/cable_main.o: EXTRA_DEFS := -DCABLE_PYTHON='"$(PYTHON)"'

$(BUILD)/%.o: %.c | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(EXTRA_DEFS) $(call layer_incs,$<) -c $< -o $@

$(BUILD)/gen/autoeq_compat_text.c: $(COMPAT_FILES) Makefile
	@mkdir -p $(dir $@)
	@{ echo '#include "autoeq_impl.h"'; \
	   echo 'const cable_autoeq_compat_file cable_autoeq_compat_files[] = {'; \
	   for f in $(COMPAT_FILES); do \
	     printf '{"%s",\n' "$$(basename $$f)"; \
	     sed -e 's/\\/\\\\/g' -e 's/"/\\"/g' -e 's/^/"/' -e 's/$$/\\n"/' $$f; \
	     echo '},'; \
	   done; \
	   echo '};'; \
	   echo 'const int cable_autoeq_compat_nfiles = (int)(sizeof cable_autoeq_compat_files / sizeof cable_autoeq_compat_files[0]);'; \
	 } > $@.tmp && mv $@.tmp $@

$(GEN_OBJS): $(BUILD)/gen/%.o: $(BUILD)/gen/%.c | $(DEPS_OK)
	$(CC) $(CFLAGS) $(LIBFLAGS) $(INCS_auto_iface/autoeq) $(SYSINCS) -c $< -o $@

# The static library serves the test programs (they reach private functions);
# programs and plug-ins outside the tree use libcable.so.
$(LIBCABLE): $(LIB_OBJS) $(GEN_OBJS)
	@rm -f $@
	ar rcs $@ $^

$(LIBSO): $(LIB_OBJS) $(GEN_OBJS) $(PRIVBLAS_OBJ)
	$(CC) $(LDFLAGS) -shared -Wl,-soname,$(SONAME) $^ $(LIBS_PRIVBLAS) -o $@
	@ln -sf libcable.so $(BUILD)/$(SONAME)

lib: $(LIBSO) $(LIBCABLE)

$(PY_SO): $(PY_OBJS) $(PRIVBLAS_OBJ) $(LIBCABLE)
	@mkdir -p $(dir $@)
	$(CC) -shared $(LDFLAGS) $^ $(LIBS_PRIVBLAS) -o $@

$(PYPKG)/%.py: python/cable/%.py
	@mkdir -p $(dir $@)
	cp $< $@

python: $(PY_SO) $(PY_FILES)

# The command line: a program over the library (linked with the static
# archive, as the tests are); libcable carries no command.
$(BUILD)/cable: $(CLI_OBJS) $(LIBCABLE)
	$(CC) $(LDFLAGS) -rdynamic $^ $(LIBS) -o $@

cable: $(BUILD)/cable
	@if [ "$(MODE)" = release ]; then ln -sf $(BUILD)/cable cable; fi

$(BUILD)/tests/%: $(BUILD)/tests/%.o $(LIBCABLE)
	$(CC) $(LDFLAGS) -rdynamic $^ $(LIBS) -o $@

# Programs written against include/cable/ only, linked with the shared library.
$(BUILD)/tests/test_api_%: tests/api/api_%.c $(LIBSO) | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(PUBINC) -I$(BUILD)/gen $< $(LDFLAGS) -L$(BUILD) -lcable -Wl,-rpath,$(abspath $(BUILD)) -lm -o $@

# The misuse cases of every CABLE_API function, generated from the headers
# (and checked against what libcable.so exports): doc/api.md, Contracts.
$(BUILD)/gen/api_misuse_gen.inc: scripts/gen_api_misuse.py $(wildcard include/cable/*.h) $(LIBSO)
	@mkdir -p $(dir $@)
	$(PYTHON) scripts/gen_api_misuse.py $@ $(LIBSO)
$(BUILD)/tests/test_api_generated: $(BUILD)/gen/api_misuse_gen.inc

# Plug-ins see the public headers only.
$(BUILD)/plugins/%.so: tests/plugins/%.c | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(PUBINC) -Itests/plugins -shared $< -o $@

# the Python package only in release builds (CPython cannot load a sanitized extension)
PY_TARGET_release := python
tests-build: $(TEST_BINS) $(API_BINS) $(PLUGINS) $(BUILD)/cable cable $(LIBSO) $(PY_TARGET_$(MODE))

# The README's test command: build and run every test program, one summary line.
check: tests-build
	@bash scripts/run-tests.sh $(BUILD)

asan:
	@$(MAKE) --no-print-directory MODE=asan DEPS_OK=$(DEPS_OK) tests-build
	@ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 UBSAN_OPTIONS=print_stacktrace=1 \
	  bash scripts/run-tests.sh build/asan

valgrind: tests-build
	@CABLE_TEST_WRAPPER="valgrind --quiet --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite,indirect" \
	  CABLE_TEST_QUICK=1 CABLE_TEST_JOBS=$${CABLE_TEST_JOBS:-$$(nproc)} bash scripts/run-tests.sh $(BUILD)

# The README's pictures (doc/img) from the knot72 scene (scripts/doc-img.sh).
doc-img: cable python
	@bash scripts/doc-img.sh

# The README's main job: the paper's knot scene on its defaults.
demo: cable python
	@bash scripts/demo.sh

scenes: cable python
	@bash scripts/scenes.sh

bench: cable tests-build $(BENCH_BINS)
	@bash scripts/bench.sh $(BUILD)

# the atlas part of make bench alone (cable.atlas on Dask; doc/atlas.md, 7)
bench-atlas: cable python
	@bash scripts/bench-atlas.sh $(BUILD)

# Stress grid (scripts/stress.sh, table in doc/stress.md); a quick subset runs in make check.
stress: cable tests-build
	@bash scripts/stress.sh $(BUILD)

# Fuzzing of the constants and s-file parsers (clang's libFuzzer).
fuzz:
	@bash scripts/fuzz.sh

# Headers, library, pkg-config file, cable and its Python package under PREFIX
# (default /usr/local; bin/cable finds PREFIX/lib/cable/python):
#   make install PREFIX=$HOME/.local
#   cc app.c $(pkg-config --cflags --libs cable)
install: $(LIBSO) $(BUILD)/cable python
	install -d $(DESTDIR)$(PREFIX)/include/cable $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/bin \
	  $(DESTDIR)$(PREFIX)/lib/cable/python/cable
	install -m 644 $(PY_FILES) $(DESTDIR)$(PREFIX)/lib/cable/python/cable/
	install -m 755 $(PY_SO) $(DESTDIR)$(PREFIX)/lib/cable/python/cable/
	install -m 644 include/cable/*.h $(DESTDIR)$(PREFIX)/include/cable/
	install -m 755 $(LIBSO) $(DESTDIR)$(PREFIX)/lib/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(PREFIX)/lib/libcable.so
	install -m 755 $(BUILD)/cable $(DESTDIR)$(PREFIX)/bin/cable
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(VERSION)|' cable.pc.in \
	  > $(DESTDIR)$(PREFIX)/lib/pkgconfig/cable.pc

clean:
	rm -rf build cable

help:
	@echo "make            build ./cable, libcable.so and the Python package (build/MODE/python); installs nothing"
	@echo "make deps       install the missing Debian packages (build, tests, benchmarks; scripts/install-deps.sh)"
	@echo "make lib        build build/MODE/libcable.so (and the static libcable.a)"
	@echo "make install    headers, libcable.so, cable.pc, cable and the Python package under PREFIX"
	@echo "make check      build and run the test suite (summary: N passed, M failed)"
	@echo "make demo       build and run the main job (the paper's knot scene)"
	@echo "make doc-img    the README's pictures (doc/img) from the knot72 scene, and its cable view screenshot"
	@echo "make asan       tests under AddressSanitizer + UBSan"
	@echo "make valgrind   tests under valgrind memcheck"
	@echo "make scenes     replay every scene in runs/"
	@echo "make bench      benchmarks, tables in doc/benchmarks.md"
	@echo "make bench-atlas  the atlas part of make bench alone (cable.atlas on 1 and 2 workers)"
	@echo "make stress     stress grid, table in doc/stress.md"
	@echo "make fuzz       fuzz the parsers (libFuzzer, 10 minutes)"

.PRECIOUS: $(BUILD)/%.o $(BUILD)/tests/%.o
-include $(LIB_OBJS:.o=.d) $(GEN_OBJS:.o=.d) $(PY_OBJS:.o=.d) $(TEST_BINS:=.d) $(API_BINS:=.d) $(BENCH_BINS:=.d) $(PLUGINS:.so=.d) $(CLI_OBJS:.o=.d)
