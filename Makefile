# The README's two commands: `make demo` and `make test`. Each installs the Debian packages
# it needs first (scripts/setup-deps.sh), then builds with cargo.
SHELL := /bin/bash
CARGO ?= cargo
export VK_DRIVER_FILES ?= /usr/share/vulkan/icd.d/lvp_icd.x86_64.json

.PHONY: demo test deps test-deps check-cargo check-clippy install-c

check-cargo:
	@command -v $(CARGO) >/dev/null || { echo "ffvk: cargo not found: install a Rust toolchain (rustup) first" >&2; exit 1; }

# make test lints with clippy: add it where the toolchain came without it (rustup's minimal
# profile), else say how.
check-clippy: check-cargo
	@$(CARGO) clippy --version >/dev/null 2>&1 || { command -v rustup >/dev/null && rustup component add clippy; } || \
		{ echo "ffvk: cargo clippy not found: install it (rustup component add clippy)" >&2; exit 1; }

deps: check-cargo
	@bash scripts/setup-deps.sh

test-deps: check-clippy
	@bash scripts/setup-deps.sh --test

demo: deps
	$(CARGO) run -- demo --out out/demo

# The workspace's tests (the suite, unit tests, examples, benches built), the doctests (the
# Rust snippets of the README and the guides under docs/, and the API's examples), the lints, the library's rustdoc without a
# warning (broken links), the library alone as a plain dependency builds it, and a crate
# outside the workspace that depends on it.
test: test-deps
	$(CARGO) test --workspace --all-targets
	$(CARGO) test --workspace --doc
	$(CARGO) clippy --workspace --all-targets -- -D warnings
	RUSTDOCFLAGS="-D warnings" $(CARGO) doc -p ffvk --no-deps --all-features --quiet
	bash scripts/check-lean-core.sh
	bash scripts/check-dependent.sh

# ffvk's C library as a system library (docs/c-api.md, "From C and C++"):
#   make install-c [PREFIX=/usr/local] [DESTDIR=staging] [LIBDIR=...] [INCLUDEDIR=...]
# builds it (cargo build --release -p ffvk-c) and installs libffvk_c.so.<version> with its
# links libffvk_c.so.<major> (the SONAME) and libffvk_c.so, libffvk_c.a, include/ffvk.h and
# lib/pkgconfig/ffvk.pc. Where the loader does not search LIBDIR, ffvk.pc's Libs carry
# -Wl,-rpath,<libdir> (RPATH=auto; yes or no force it). FFVK_C_LIB_DIR=<dir> installs the
# libraries cargo already built there instead of building (the tests pass target/<profile>).
PREFIX ?= /usr/local
LIBDIR ?= $(PREFIX)/lib
INCLUDEDIR ?= $(PREFIX)/include
DESTDIR ?=
RPATH ?= auto
FFVK_C_LIB_DIR ?=

install-c:
ifeq ($(FFVK_C_LIB_DIR),)
	@$(MAKE) --no-print-directory check-cargo
	$(CARGO) build --release -p ffvk-c
	FFVK_C_LIB_DIR="$(or $(CARGO_TARGET_DIR),$(CURDIR)/target)/release" PREFIX="$(PREFIX)" LIBDIR="$(LIBDIR)" \
		INCLUDEDIR="$(INCLUDEDIR)" DESTDIR="$(DESTDIR)" RPATH="$(RPATH)" bash scripts/install-c.sh
else
	FFVK_C_LIB_DIR="$(FFVK_C_LIB_DIR)" PREFIX="$(PREFIX)" LIBDIR="$(LIBDIR)" INCLUDEDIR="$(INCLUDEDIR)" \
		DESTDIR="$(DESTDIR)" RPATH="$(RPATH)" bash scripts/install-c.sh
endif
