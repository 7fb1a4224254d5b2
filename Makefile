# The two commands of the README. Both install missing Debian packages first
# (tools/install-deps.sh), then configure and build a Release binary build/hvsph.
BUILD ?= build
JOBS  ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?=

.PHONY: all deps build demo check bench figures analyze sanitize clean

all: build

deps:
	@bash tools/install-deps.sh

build: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

# The demo builds hvsph alone, quietly: cmake's output goes to $(BUILD)/build.log, shown
# whole when the build fails; compiler warnings (none expected) are counted, not hidden.
demo: deps
	@mkdir -p $(BUILD)
	@echo "hvsph demo: building $(BUILD)/hvsph (log in $(BUILD)/build.log)"
	@{ cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) && \
	   cmake --build $(BUILD) -j $(JOBS) --target hvsph; } >$(BUILD)/build.log 2>&1 || \
	 { cat $(BUILD)/build.log; echo "make demo: the build failed (above; $(BUILD)/build.log)" >&2; exit 1; }
	@n=$$(grep -c 'warning:' $(BUILD)/build.log || true); if [ "$$n" -gt 0 ]; then \
	 echo "make demo: the compiler warned $$n times (see $(BUILD)/build.log)"; fi
	@bash tools/demo.sh $(BUILD)

check: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) --timeout 900

bench: build
	@$(BUILD)/hvsph bench

# The documentation's pictures (tools/README.md, "Figures"): every tools/figures/*.sh,
# or only those named in FIGURES (make figures FIGURES="sod-shock-tube taylor-bar"), with
# HVSPH, RUNS (default out/validation, `hvsph validate --scale 1 -o out/validation`:
# hours) and OUT (default docs/img) from the environment. A figure whose runs are missing
# is skipped; the target fails if any figure failed.
figures: build
	@bash tools/install-deps.sh --docs
	@HVSPH="$${HVSPH:-$(BUILD)/hvsph}" bash tools/figures/make-figures.sh $(FIGURES)

# Static analysis of the library, build/hvsph and the tests (clang's analyser through
# scan-build, a Debug build in $(BUILD)-analyze): fails when it reports anything; the
# HTML report is in $(BUILD)-analyze/report. Not part of check (docs/design.md,
# "Static analysis").
analyze:
	@bash tools/install-deps.sh --analyze
	@rm -rf $(BUILD)-analyze
	@scan-build-14 -o $(BUILD)-analyze/report cmake -S . -B $(BUILD)-analyze \
	  -DCMAKE_BUILD_TYPE=Debug $(CMAKE_FLAGS) >/dev/null
	@scan-build-14 -o $(BUILD)-analyze/report --status-bugs \
	  cmake --build $(BUILD)-analyze -j $(JOBS)

# The tests on a build with the address and undefined-behaviour sanitizers (gcc's
# ASan and UBSan, optimised with debug information, in $(BUILD)-sanitize): a memory
# error, a leak or undefined behaviour fails the test it happens in. Not part of check
# (docs/design.md, "Sanitizers").
sanitize: deps
	@cmake -S . -B $(BUILD)-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHVSPH_SANITIZE=ON \
	  $(CMAKE_FLAGS) >/dev/null
	@cmake --build $(BUILD)-sanitize -j $(JOBS)
	@cd $(BUILD)-sanitize && ctest --output-on-failure -j $(JOBS) --timeout 3600

clean:
	rm -rf $(BUILD) $(BUILD)-analyze $(BUILD)-sanitize
