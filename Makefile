# Two commands matter: `make play` and `make test`. Everything they need (OS packages, the
# engine, the extension, the import) is set up on the way, and skipped when already done.
SHELL := bash
.SHELLFLAGS := -eu -o pipefail -c
.DEFAULT_GOAL := play

# Godot writes settings and caches under XDG folders: keep them inside the project.
export XDG_CONFIG_HOME := $(CURDIR)/.xdg/config
export XDG_DATA_HOME := $(CURDIR)/.xdg/data
export XDG_CACHE_HOME := $(CURDIR)/.xdg/cache

GODOT := tools/godot
BUILD := .build
CMAKE_GENERATOR := $(shell command -v ninja >/dev/null 2>&1 && echo Ninja || echo "Unix Makefiles")
CMAKE_CONFIGURE = cmake -S gdextension -G "$(CMAKE_GENERATOR)" -Wno-dev
JOBS := $(shell nproc 2>/dev/null || echo 2)
# Extra arguments after `--`: for the game (e.g. make play ARGS=--system-check), or without a
# display for its autopilot (make play ARGS=--autopilot-seconds=20)
ARGS ?=
# Extra arguments for the Godot test runner, e.g. make test-godot TEST_ARGS=--filter=binding
TEST_ARGS ?=
# Seconds the benchmark runs each loop.
BENCH_SECONDS ?= 10
# Seconds make soak runs the level.
SOAK_SECONDS ?= 600

.PHONY: help play edit test check deps engine schema build build-release import test-native test-godot \
	test-godot-unit lint test-schema pong-demo test-ahead \
	export test-export export-server test-export-server dist test-dist test-windowed test-net bench-net bench soak sanitize analyze export-study \
	test-analysis addon test-addon test-editor test-kernel test-rt test-bare clean distclean \
	build-windows test-windows test-person

## help: the documented targets, one line each (this list)
help:
	@python3 tools/make_help.py Makefile

## deps: install the missing OS packages
## apt-get; sudo when not root.
deps:
	@tools/install-deps.sh

## engine: provision Godot 4.5+ if needed and say which one runs
engine: deps
	@$(GODOT) --which

## schema: write what the schemas define (C++ structs, GDScript values, docs/values.md)
## From every *.schema.toml; make build does it first, make lint checks it is current.
schema:
	@python3 tools/schema/generate.py

## build: build the development library and the doctests
## RelWithDebInfo, with the development tools (the scripted devices the tests use), loaded by
## this project's editor and debug runs.
build: engine schema
	@$(CMAKE_CONFIGURE) -B $(BUILD)/debug -DCMAKE_BUILD_TYPE=RelWithDebInfo \
		-DHAPTICS_TARGET=template_debug -DHAPTICS_DEV_TOOLS=ON >/dev/null
	@cmake --build $(BUILD)/debug -j $(JOBS)

## build-release: build the product library that exports and the addon ship
## Optimised, without development tools; bundled by exports and packed into the addon.
build-release: engine schema
	@$(CMAKE_CONFIGURE) -B $(BUILD)/release -DCMAKE_BUILD_TYPE=Release \
		-DHAPTICS_TARGET=template_release -DHAPTICS_DEV_TOOLS=OFF -DHAPTICS_BUILD_TESTS=OFF \
		-DHAPTICS_BUILD_BENCH=OFF >/dev/null
	@cmake --build $(BUILD)/release -j $(JOBS) --target haptics

## import: let Godot import the project
## The extension is listed first: a fresh import that registers a class otherwise crashes (Godot
## #111048; docs/troubleshooting.md).
import: build
	@mkdir -p .godot
	@echo "res://addons/haptics/haptics.gdextension" > .godot/extension_list.cfg
	@$(GODOT) --headless --path . --import >$(BUILD)/import.log 2>&1 || \
		{ tail -n 30 $(BUILD)/import.log; echo "import failed (log: $(BUILD)/import.log)"; exit 1; }

## edit: open this project in the Godot editor
## F5/F6 play the game from it.
edit: import
	@$(GODOT) --editor --path .

## play: play the game (headless under the autopilot when there is no display)
## Without a display: level 1 headless under the autopilot (a test driver:
## tests/drivers/game_autopilot.tscn).
play: import
	@if [[ -n "$${DISPLAY:-}" || -n "$${WAYLAND_DISPLAY:-}" ]]; then \
		$(GODOT) --path . -- $(ARGS); \
	else \
		echo "No display: running the level headless under the autopilot."; \
		$(GODOT) --headless --path . res://tests/drivers/game_autopilot.tscn -- $(ARGS); \
	fi

## pong-demo: a headless computer-vs-computer Haptic Battle Pong match
## The servo stepped by the game, faster than real time; prints the winner and simulated vs wall
## seconds (tests/drivers/pong_demo.tscn). ARGS=--pong-health=N sets each player's health
## (default 15), --pong-players=4 plays on the square four-player court.
pong-demo: import
	@$(GODOT) --headless --path . res://tests/drivers/pong_demo.tscn -- $(ARGS)

## test: every suite: what CI runs (about 50 minutes on this 2-core machine)
## Any failure fails the target; each suite's seconds are printed at the end. While the first
## suites run, test-ahead prepares what later ones need on the other core, and is done before
## the suites that measure time begin (tools/ci/run-suites.sh).
TEST_SUITES := test-native test-godot lint test-schema test-analysis export test-net \
	test-windowed test-person test-rt
# test-ahead is over before the export (it builds the release library the export bundles),
# and so before the first suite that measures time (processes, sockets, windows). The export
# comes first as the person plays it too. Then two lanes side by side: the suites whose
# bounds need a core (the VMs; the exported server's match at 50 ms, which a starved peer
# skews), and the packages' suites niced beside them (they share the exports; none measures
# time).
TEST_LANE_VM := test-kernel test-export-server
TEST_LANE_PACKAGES := test-export test-dist test-addon test-editor test-bare test-windows
test: import
	@tools/ci/run-suites.sh --ahead test-ahead --join-before export \
		--lanes "$(TEST_LANE_VM)" "$(TEST_LANE_PACKAGES)" $(TEST_SUITES)
	@echo "make test: all suites passed"

## test-ahead: the builds and downloads later suites need, made ahead
## The release library, the Windows build, the VM tests' kernels and the bare systems' roots
## (as root); make test runs it niced beside its first suites.
test-ahead: build-release build-windows
	@for suite in $(KERNEL_SUITES); do tools/kernel/fetch.sh $$suite >/dev/null; done
	@if [[ $$(id -u) -eq 0 ]]; then \
		tools/bare/root.sh bookworm >/dev/null && tools/bare/root.sh bullseye >/dev/null; fi

## check: the quick loop: build, doctests, the GDScript unit suites, lint (under 5 minutes)
## Run it before every commit; make test is the whole of it plus every scenario, process,
## export, VM and Wine suite.
check: build test-native test-godot-unit lint
	@echo "make check: build, doctests, GDScript unit suites and lint passed"

## test-godot-unit: the GDScript suites that are quick (no scenario, no extra process)
## Suites that run whole scenes for seconds or start other processes say const SLOW := true.
test-godot-unit: import
	@$(GODOT) --headless --path . res://tests/runner/runner.tscn -- --warnings-as-errors --quick \
		$(TEST_ARGS)

## test-native: the C++ doctest suite
## Through CTest.
test-native: build
	@ctest --test-dir $(BUILD)/debug --output-on-failure -j $(JOBS)

## build-windows: cross-build the extension for Windows (MinGW-w64)
## x86_64, hidapi and libusb from Debian's sources linked in, as
## addons/haptics/bin/libhaptics.windows.*.dll, and the doctests as an .exe; checks the DLLs
## import only Windows' own DLLs (tools/windows/build.sh).
build-windows: engine
	@nice -n 19 tools/windows/build.sh

## test-windows: the doctest suite under Wine, and the DLLs' imports
## Every test but the Linux-only ones (counted and listed) (tools/windows/test.sh).
test-windows: build build-windows
	@nice -n 19 tools/windows/test.sh

## test-godot: every GDScript suite, headless, with the real extension
## Two runners side by side, each on every other file (tools/ci/godot-shards.sh).
test-godot: import
	@tools/ci/godot-shards.sh 2 --warnings-as-errors $(TEST_ARGS)

## test-windowed: the game in a window (Xvfb) under its autopilot, then its menu
## A few seconds under the autopilot, then the product's main menu under its system check; fails
## on a non-zero exit, an error or any leak reported at exit (tools/test-windowed.sh).
test-windowed: import
	@tools/test-windowed.sh

## test-person: a scripted person plays the windowed game with keys and mouse (Xvfb)
## The real game in a window (Xvfb, openbox), started as `make play` starts it (and the exported
## one when .export/linux has it); the person acts only through input events (xdotool) at
## places it reads off screenshots (tesseract, and the sub, ball and paddles by colour): level 1
## through the pause menu and Settings, steered with the keys to the goal, the goal screen's
## Menu, the window closed (exit 0); Pong against the computer with a clumsy mouse hand (a
## serve within 5 s, a rally of six contacts); a network match of two people at two screens
## through the lobby (the host from source, the guest exported); the maze study from its start
## screen to the thank-you (the shipped build only). Fails on any error or X error line;
## screenshots in .build/person/<test>/ (tests/person, about 11 minutes).
test-person: import
	@tools/analysis/run.sh -m pytest tests/person -q -rsx -p no:cacheprovider -s --durations=0

## lint: the schemas current, include layers, the typed boundary, gdlint, gdformat, clang-format
## the C++ layers' include directions and the 400-line limit (tools/check-includes.py),
## the GDScript folders' layers and the Haptics door (tools/check-gd-layers.py), the typed
## boundary (tools/check-boundary.py: native methods with maps, calls by name, untyped @rpc,
## citations of files outside the repository), gdlint
## (400 lines a file) and gdformat --check over addons/, game/ and tests/ (gdtoolkit,
## pinned, in .venv), clang-format (Debian's, .clang-format: Godot's style) over the C++,
## and the test of tools/check-product.sh on fake packs (tools/test-check-product.sh)
lint: deps
	@python3 tools/schema/generate.py --check
	@python3 tools/check-includes.py
	@python3 tools/check-gd-layers.py
	@python3 tools/check-boundary.py
	@tools/test-check-product.sh
	@tools/gdtoolkit.sh gdlint addons game tests
	@tools/gdtoolkit.sh gdformat --check addons game tests
	@find gdextension/src gdextension/tests gdextension/bench gdextension/vm_tests gdextension/rt_probe -name '*.h' -o -name '*.cpp' | \
		sort | xargs clang-format --dry-run -Werror
	@echo "clang-format: the C++ is formatted"

## export: a self-contained Linux build in .export/linux/
## ./haptic-game starts it with the C library and libraries shipped in runtime/
## (tools/bundle-runtime.sh).
export: import build-release
	@tools/export.sh

## test-export: export, then run the copy in an emptied environment
## A copy outside the project with an emptied environment, headless and windowed (Xvfb), under
## the game's system check: exit 0, extension loaded, main menu shown, every library from the
## bundle except the system's GPU driver, no driver of tests/ or tools/ in the pack
## (tools/test-export.sh).
test-export: export
	@tools/test-export.sh

## export-server: the dedicated Pong server, self-contained, in .export/linux-server/
## ./haptic-pong-server --headless -- --server [--port=P]
export-server: import build-release
	@tools/export.sh server

## test-export-server: the exported server referees a match between two clients
## Started with an emptied environment; the clients run from the source tree: exit 0, no error
## in any log.
test-export-server: export-server
	@tools/check-product.sh .export/linux-server
	@HAPTICS_SERVER=.export/linux-server/haptic-pong-server \
		tools/analysis/run.sh -m pytest tests/net/test_exported_server.py -q -p no:cacheprovider

## test-bare: the exported game and server on minimal Debian 12 and 11 roots
## Without any graphics package (debootstrap, built once into .bare/), run as an ordinary user:
## they start and exit 0 without an error line; on Debian 11 a windowed start is stopped by the
## launcher naming the system's glibc (tools/bare/test-bare.sh). The first run downloads and
## builds the roots (minutes; docs/supported-systems.md), later runs reuse them.
test-bare: export export-server
	@tools/bare/test-bare.sh

## dist: the player's archive, .export/haptic-game-linux-x86_64.tar.gz
## The self-contained build, a player README (controls, devices, permissions) and the udev
## rules; prints its size (tools/dist.sh).
dist: export
	@tools/dist.sh

## test-dist: make dist, then check the archive's contents
## Unpacks the archive and checks its contents (tools/test-dist.sh).
test-dist: dist
	@tools/test-dist.sh

## addon: the Godot addon and its Asset Library zip
## Assembled from the sources into .build/addon/addons/haptics/ (the scripts, the probe scene,
## the materials, the Linux and Windows libraries, the editor plugin), zipped as
## .build/addon/haptics-addon-<version>.zip; without MinGW-w64, Linux's alone, as
## haptics-addon-<version>-linux-only.zip (it says so).
addon: import build-release $(if $(shell command -v x86_64-w64-mingw32-g++),build-windows)
	@tools/build-addon.sh

## test-addon: install the addon into a small game the README's way and play it
## A small platformer we did not build it into, in a temporary folder: one import without a
## crash, then a steady push from a tile wall on every physics frame of a slow run-up's push, an
## impact, the wall let go of once walked away from, no error output (tools/test-addon.sh).
test-addon: addon
	@tools/test-addon.sh

## test-editor: a developer's first hour with the addon in the GUI editor (Xvfb)
## In one session of an editor started by tools/godot: a project that has never seen the addon
## gets the zip unpacked while the editor runs, enables the plugin, creates a HapticProbe and
## plays the scene (F6); the game must feel the floor, nothing may print an error, and closing
## the editor must not ask anything (tools/test-editor.sh).
test-editor: addon
	@tools/test-editor.sh

## test-kernel: our device stack against the real Linux drivers (QEMU)
## Debian 12's kernel and Debian testing's (each fetched once into .kernel/) boot under QEMU
## with the VM test program (gdextension/vm_tests), whose device models are real devices there
## (uhid, uinput, USB gadgets); every backend's transport end to end through the servo, unplug
## and replug (tools/kernel/run.sh). KERNEL_SUITES=bookworm runs one.
KERNEL_SUITES ?= bookworm testing
test-kernel: build
	@for suite in $(KERNEL_SUITES); do tools/kernel/run.sh $(BUILD)/debug/haptics_vm_tests $$suite || exit 1; done

## test-rt: the servo as an ordinary user gets it (RealtimeKit)
## A private system bus, polkitd and RealtimeKit started for the test, the servo run as
## 'nobody', the kernel's view of its thread checked against its stats (SCHED_RR from
## RealtimeKit, its spin learned; with /dev/cpu_dma_latency given as the udev rule gives it,
## the hold taken while it runs and released when it stops; a nice level; nothing)
## (tools/rt/test-rtkit.sh).
test-rt: build
	@tools/rt/test-rtkit.sh $(BUILD)/debug/haptics_rt_probe

## bench: the benchmarks: numbers and ratios, JSON in .bench/
## servo loop vs naive loop, the force model's and the proxy's tick cost, each device
## backend's tick cost and protocol rate against its scripted transport, the game's
## physics-frame and probe cost, the servo next to cyclictest idle / under CPU load / under
## rendering load, the end-to-end latency, headless Pong matches' speed against real time, and
## a player's numbers beside the autopilot's (tests/person/bench_person.py: level 1's time to
## the goal and frame time in a 1280x720 window, a Pong minute's contacts and longest rally)
## (numbers and ratios, not tests; JSON in .bench/)
bench: import
	@$(CMAKE_CONFIGURE) -B $(BUILD)/bench -DCMAKE_BUILD_TYPE=Release -DHAPTICS_BUILD_EXTENSION=OFF \
		-DHAPTICS_BUILD_TESTS=OFF >/dev/null
	@cmake --build $(BUILD)/bench -j $(JOBS) --target haptics_bench haptics_device_bench haptics_rt_bench
	@mkdir -p .bench
	@$(BUILD)/bench/haptics_bench --seconds $(BENCH_SECONDS) --json .bench/servo.json
	@tools/rt/bench-users.sh $(BUILD)/bench/haptics_rt_bench $(CURDIR) .bench/rt.json
	@$(BUILD)/bench/haptics_device_bench --seconds 1 --json .bench/devices.json
	@$(GODOT) --headless --path . --fixed-fps 50 res://tests/bench/game_bench.tscn -- \
		--frames=1500 --json=.bench/game.json
	@$(GODOT) --headless --path . res://tests/bench/pong_bench.tscn -- --json=.bench/pong.json
	@tools/analysis/run.sh tests/person/bench_person.py --json .bench/person.json

## soak: level 1 under the autopilot for SOAK_SECONDS with the servo at 1 kHz
## 10 minutes by default; prints rate drift, telemetry drops, resident memory growth and
## lateness against their bounds (tests/soak/soak.gd; not part of make test).
soak: import
	@$(GODOT) --headless --path . res://tests/soak/soak.tscn -- --seconds=$(SOAK_SECONDS)

## sanitize: the doctests under ThreadSanitizer, then AddressSanitizer+UBSan
sanitize: deps
	@for s in thread address; do \
		$(CMAKE_CONFIGURE) -B $(BUILD)/sanitize-$$s -DCMAKE_BUILD_TYPE=RelWithDebInfo \
			-DHAPTICS_BUILD_EXTENSION=OFF -DHAPTICS_BUILD_BENCH=OFF -DHAPTICS_SANITIZE=$$s >/dev/null; \
		cmake --build $(BUILD)/sanitize-$$s -j $(JOBS); \
		ctest --test-dir $(BUILD)/sanitize-$$s --output-on-failure; \
	done

## analyze: a study's figures, report.md and summary.json
## Into STUDY/analysis.
analyze:
	@if [[ -z "$(STUDY)" ]]; then \
		echo "usage: make analyze STUDY=<study folder> [ANALYZE_ARGS=--skip-invalid]" >&2; exit 2; fi
	@tools/analysis/run.sh analyze.py "$(STUDY)" $(ANALYZE_ARGS)

## export-study: every participant of a study in one CSV
## OUT, default STUDY/all.csv.
export-study:
	@if [[ -z "$(STUDY)" ]]; then echo "usage: make export-study STUDY=<folder> [OUT=file.csv]" >&2; exit 2; fi
	@tools/analysis/run.sh export_csv.py "$(STUDY)" "$(or $(OUT),$(STUDY)/all.csv)"

## test-analysis: the study analysis tool's pytest suite
## Hand-computed statistics.
test-analysis:
	@tools/analysis/run.sh -m pytest tools/analysis/tests -q

## test-schema: a newcomer's change in a scratch copy: a schema field, a new renderer
## In a copy of the working tree, one field added to one schema entry must reach C++ (built) and
## GDScript typed and documented, and a new renderer must register by one row and render
## (tests/schema, about a minute).
test-schema: engine
	@tools/analysis/run.sh -m pytest tests/schema -q -p no:cacheprovider

## test-net: the network tests: real peers through a relay on 127.0.0.1
## The UDP relay that gives loopback latency, jitter and loss, then networked Pong with headless
## peers through it (tests/net, about 8 minutes). Two tests at a time (pytest-xdist): most of a
## match is waiting on real time, and every bound is one a loaded machine meets.
test-net: import
	@tools/analysis/run.sh -m pytest tools/net/tests tests/net -q -p no:cacheprovider --durations=15 \
		--ignore=tests/net/test_exported_server.py -n 2

## bench-net: networked Pong's numbers for each network setting
## networked Pong's bytes/s, hand-off gap, divergence, corrections, ball states
## taken, and each headless peer's CPU share and peak memory for each network setting, the
## issue's rough network included (numbers, not tests; JSON in .bench/net.json)
bench-net: import
	@tools/analysis/run.sh tests/net/bench_net.py --peers 2 4 --json .bench/net.json

## clean: remove the build outputs
## build outputs (keeps the provisioned engine and Python tools)
clean:
	rm -rf $(BUILD) addons/haptics/bin .export .bench

## distclean: remove everything the project created
## everything the project created, including the engine and .godot
distclean: clean
	rm -rf .engine .xdg .venv .godot .bare
