# cable: elastic cable knots and links by numerical continuation.
# One hand-written makefile: settings, then rules.  `make help` lists the targets.

CC      ?= gcc
MODE    ?= release
BUILD   := build/$(MODE)

MODULES := continuation auto_iface equations bc graphics
WARN    := -Wall -Wextra -Werror -Wshadow -Wpointer-arith -Wcast-align \
           -Wstrict-prototypes -Wmissing-prototypes -Wwrite-strings \
           -Wundef -Wformat=2 -Wvla -Wdouble-promotion -Wnull-dereference
CSTD    := -std=c11 -D_POSIX_C_SOURCE=200809L
INCS    := $(addprefix -I,$(MODULES)) -Itests -I/usr/include/suitesparse
OPT_release := -O2 -g
OPT_asan    := -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all
OPT_fuzz    := -O1 -g -fsanitize=fuzzer-no-link,address,undefined
CFLAGS  := $(CSTD) $(WARN) $(OPT_$(MODE)) $(INCS) -MMD -MP -fPIC $(EXTRA_CFLAGS)
SAN_LD_asan := -fsanitize=address,undefined
LDFLAGS := $(SAN_LD_$(MODE)) $(EXTRA_LDFLAGS)
LIBS    := -lsundials_kinsol -lsundials_sunlinsolklu -lsundials_sunmatrixsparse \
           -lsundials_nvecserial -lsundials_generic -lklu \
           -lgsl -llapacke -llapack -lblas -lcairo -ldl -lpthread -lm

LIB_SRCS := $(filter-out auto_iface/cable_main.c,$(wildcard $(addsuffix /*.c,$(MODULES))))
LIB_OBJS := $(LIB_SRCS:%.c=$(BUILD)/%.o)
TEST_SRCS := $(wildcard tests/test_*.c)
TEST_BINS := $(TEST_SRCS:tests/%.c=$(BUILD)/tests/%)
BENCH_SRCS := $(wildcard tests/bench_*.c)
BENCH_BINS := $(BENCH_SRCS:tests/%.c=$(BUILD)/tests/%)
PLUGIN_SRCS := $(wildcard tests/plugins/*.c)
PLUGINS  := $(PLUGIN_SRCS:tests/plugins/%.c=$(BUILD)/plugins/%.so)
LIBCABLE := $(BUILD)/libcable.a
DEPS_OK  := build/.deps-ok

.PHONY: all check asan valgrind demo scenes bench stress fuzz clean help deps tests-build

all: cable

# Dependencies come from Debian; the script installs only what is missing.
$(DEPS_OK): scripts/install-deps.sh
	@bash scripts/install-deps.sh
	@mkdir -p build && touch $@
deps: $(DEPS_OK)

$(BUILD)/%.o: %.c | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -c $< -o $@

$(LIBCABLE): $(LIB_OBJS)
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/cable: $(BUILD)/auto_iface/cable_main.o $(LIBCABLE)
	$(CC) $(LDFLAGS) -rdynamic $^ $(LIBS) -o $@

cable: $(BUILD)/cable
	@if [ "$(MODE)" = release ]; then ln -sf $(BUILD)/cable cable; fi

$(BUILD)/tests/%: $(BUILD)/tests/%.o $(LIBCABLE)
	$(CC) $(LDFLAGS) -rdynamic $^ $(LIBS) -o $@

$(BUILD)/plugins/%.so: tests/plugins/%.c | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -shared $< -o $@

tests-build: $(TEST_BINS) $(PLUGINS) $(BUILD)/cable cable

# The README's test command: build and run every test program, one summary line.
check: tests-build
	@bash scripts/run-tests.sh $(BUILD)

asan:
	@$(MAKE) --no-print-directory MODE=asan tests-build
	@ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 UBSAN_OPTIONS=print_stacktrace=1 \
	  bash scripts/run-tests.sh build/asan

valgrind: tests-build
	@CABLE_TEST_WRAPPER="valgrind --quiet --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite,indirect" \
	  CABLE_TEST_QUICK=1 bash scripts/run-tests.sh $(BUILD)

# The README's main job: the paper's knot scene on its defaults.
demo: cable
	@bash scripts/demo.sh

scenes: cable
	@bash scripts/scenes.sh

bench: cable tests-build $(BENCH_BINS)
	@bash scripts/bench.sh $(BUILD)

# Stress grid (scripts/stress.sh, table in doc/stress.md); a quick subset runs in make check.
stress: cable tests-build
	@bash scripts/stress.sh $(BUILD)

# Fuzzing of the constants, script and s-file parsers (clang's libFuzzer).
fuzz:
	@bash scripts/fuzz.sh

clean:
	rm -rf build cable

help:
	@echo "make            build ./cable"
	@echo "make check      build and run the test suite (summary: N passed, M failed)"
	@echo "make demo       build and run the main job (the paper's knot scene)"
	@echo "make asan       tests under AddressSanitizer + UBSan"
	@echo "make valgrind   tests under valgrind memcheck"
	@echo "make scenes     replay every scene in runs/"
	@echo "make bench      benchmarks, tables in doc/benchmarks.md"
	@echo "make stress     stress grid, table in doc/stress.md"
	@echo "make fuzz       fuzz the parsers (libFuzzer, 10 minutes)"

.PRECIOUS: $(BUILD)/%.o $(BUILD)/tests/%.o
-include $(LIB_OBJS:.o=.d) $(TEST_BINS:=.d) $(BENCH_BINS:=.d) $(PLUGINS:.so=.d) $(BUILD)/auto_iface/cable_main.d
