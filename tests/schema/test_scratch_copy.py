"""A newcomer's two changes, made in a scratch copy of the project with no other hand edit:

1. one field added to one schema entry (a contact's grip) reaches the C++ struct, its codec
   and its checks, the GDScript class (typed, documented) and docs/values.md; a script that
   misspells it does not parse; and bytes GDScript writes decode in C++ and back;
2. a new renderer (a spring to the workspace centre, the fifth) is its folder plus one row in
   system/renderer_table.h: the system lists it, renders it, takes and checks its settings.

The copy is the working tree's files (tracked and untracked, not ignored); the C++ is built
from it (the engine-free libraries, not the Godot extension) and Godot imports it.
Run: tools/analysis/run.sh -m pytest tests/schema -q      (make test-schema; a few minutes)
"""

import os
import re
import shutil
import subprocess
import textwrap
from pathlib import Path

import pytest

PROJECT = Path(__file__).resolve().parents[2]
GRIP = (
    'fields.grip_n = { type = "float", min = 0.0, max = 5.0, unit = "N", default = 0.25, '
    'doc = "How hard the surface holds a hand that slides along it." }\n'
)


def run(args, cwd, timeout=1800, check=True):
    done = subprocess.run(args, cwd=cwd, capture_output=True, text=True, timeout=timeout)
    if check and done.returncode != 0:
        raise AssertionError(f"{' '.join(map(str, args))} exited {done.returncode}:\n"
                             f"{done.stdout[-3000:]}\n{done.stderr[-3000:]}")
    return done


@pytest.fixture(scope="module")
def scratch(tmp_path_factory):
    root = tmp_path_factory.mktemp("scratch") / "project"
    listed = run(["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"], PROJECT)
    for name in filter(None, listed.stdout.split("\0")):
        source = PROJECT / name
        if source.is_file():
            (root / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, root / name)
    # The engine and Python tools are the project's (ignored, provisioned once); the import
    # cache only saves time (Godot re-imports what changed).
    for ignored in (".engine", ".venv"):
        if (PROJECT / ignored).exists():
            os.symlink(PROJECT / ignored, root / ignored)
    if (PROJECT / ".godot").is_dir():
        shutil.copytree(PROJECT / ".godot", root / ".godot", symlinks=True,
                        ignore=shutil.ignore_patterns("editor", "shader_cache"))
    _add_the_grip(root)
    _add_a_spring_renderer(root)
    generated = run(["python3", "tools/schema/generate.py"], root)
    (root / "generate.log").write_text(generated.stdout)
    return root


def _add_the_grip(root):
    schema = root / "gdextension/src/core/render/frame.schema.toml"
    text = schema.read_text()
    start = text.index("[values.Contact]")
    end = text.find("\n[", start + 1)
    end = len(text) if end < 0 else end
    schema.write_text(text[:end].rstrip("\n") + "\n" + GRIP + text[end:])


def _add_a_spring_renderer(root):
    folder = root / "gdextension/src/renderers/spring"
    folder.mkdir()
    (folder / "spring.schema.toml").write_text(textwrap.dedent('''\
        [schema]
        doc = "A spring to the workspace centre: the smallest renderer there is."
        cpp = "spring.gen.h"
        gdscript = "game/spring"
        gd_constants = "SpringFacts"

        [enums.SpringForce]
        doc = "Its force components."
        values = ["pull"]
        index_suffix = "_FORCE"

        [values.SpringConfig]
        gd = "SpringSettings"
        settings = true
        doc = "The spring."
        fields.stiffness_n_per_m = { type = "float", min = 0.0, max = 500.0, unit = "N/m", default = 50.0, doc = "k." }
        '''))
    (folder / "spring_renderer.h").write_text(textwrap.dedent('''\
        #pragma once

        // Pulls the hand to the workspace centre, -k x.

        #include "core/base/seqlock.h"
        #include "core/render/renderer.h"
        #include "core/render/renderer_channels.h"
        #include "core/render/renderer_info.h"
        #include "core/render/renderer_port.h"
        #include "core/render/settings_inbox.h"
        #include "renderers/spring/spring.gen.h"

        namespace haptics {

        struct SpringChannels : RendererChannels {
        \tSeqlock<SpringConfig> settings;
        };

        class SpringRenderer final : public Renderer {
        public:
        \tusing Config = SpringConfig;
        \tusing Channels = SpringChannels;
        \tusing Port = NoPort;
        \tstatic const RendererInfo &info() {
        \t\tstatic const RendererInfo INFO{ SPRING_FORCE_NAMES, {} };
        \t\treturn INFO;
        \t}
        \texplicit SpringRenderer(SpringChannels &r_channels) :
        \t\t\tinbox_(r_channels.settings) {}
        \tvoid pick_up_settings(double, bool p_restart) override { inbox_.take(config_, p_restart); }
        \tvoid reset() override {}
        \tvoid render(const RenderInput &p_input, RenderResult &r_result) override {
        \t\tr_result.forces = ForceComponents{};
        \t\tr_result.forces.parts[PULL_FORCE] = p_input.device.position_m * -config_.stiffness_n_per_m;
        \t\tr_result.forces.continuous = r_result.forces.parts[PULL_FORCE];
        \t\tr_result.continuous = r_result.forces.continuous;
        \t\tr_result.flags = 0;
        \t}

        private:
        \tSettingsInbox<SpringConfig> inbox_;
        \tSpringConfig config_;
        };

        } // namespace haptics
        '''))
    table = root / "gdextension/src/system/renderer_table.h"
    text = table.read_text()
    last = "\tX(VEHICLE, vehicle, VehicleRenderer)\n"
    assert last in text
    table.write_text(text.replace(last, "\tX(VEHICLE, vehicle, VehicleRenderer) \\\n\tX(SPRING, spring, SpringRenderer)\n"))


def test_the_generator_wrote_only_what_the_changes_ask_for(scratch):
    written = set(re.findall(r"schema: wrote (\S+)", (scratch / "generate.log").read_text()))
    assert written == {
        "gdextension/src/core/render/frame.gen.h",
        "addons/haptics/values/haptic_contact.gd",
        "addons/haptics/values/haptic_frame.gd",  # its layout id: it holds contacts
        # And their 3D forms (gd3), the same fields as 3D game vectors.
        "addons/haptics/values/haptic_contact_3d.gd",
        "addons/haptics/values/haptic_frame_3d.gd",
        "gdextension/src/renderers/spring/spring.gen.h",
        "game/spring/spring_settings.gd", "game/spring/spring_settings.gd.uid",
        "game/spring/spring_facts.gd", "game/spring/spring_facts.gd.uid",
        "docs/values.md",
    }, written
    run(["python3", "tools/schema/generate.py", "--check"], scratch)


def test_the_field_is_typed_and_documented_on_both_sides(scratch):
    header = (scratch / "gdextension/src/core/render/frame.gen.h").read_text()
    assert re.search(r"double grip_n\{ 0\.25 \};", header)
    assert re.search(r'"grip_n".*\.min = 0(\.0)?, \.max = 5(\.0)?', header)
    script = (scratch / "addons/haptics/values/haptic_contact.gd").read_text()
    assert "var grip_n: float = 0.25" in script
    assert re.search(r"## How hard the surface holds .* Unit: N\. Range \[0\.0, 5\.0\]\.\nvar grip_n", script)
    assert "grip_n" in (scratch / "docs/values.md").read_text()


@pytest.fixture(scope="module")
def built(scratch):
    """The engine-free libraries of the scratch copy, and a program on them."""
    build = scratch / ".build/scratch"
    # Unoptimised, without debug records: the test asks only that the field compiles and
    # carries its value, and this is the quickest build that shows it.
    run(["cmake", "-S", "gdextension", "-B", build, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Debug",
         "-DCMAKE_CXX_FLAGS_DEBUG=-O0", "-DHAPTICS_BUILD_EXTENSION=OFF", "-DHAPTICS_BUILD_TESTS=OFF", "-DHAPTICS_BUILD_BENCH=OFF"], scratch)
    run(["nice", "-n", "10", "cmake", "--build", build, "--target", "haptics_system", "-j", "2"], scratch,
        timeout=3600)
    program = scratch / "probe.cpp"
    program.write_text(PROBE)
    libraries = [build / f"libhaptics_{name}.a" for name in ("system", "devices", "renderers", "core")]
    system_libs = run(["pkg-config", "--libs", "hidapi-hidraw", "libusb-1.0"], scratch).stdout.split()
    includes = ["-I", scratch / "gdextension/src", "-I", build / "generated"]
    run(["g++", "-std=c++20", "-O1", *includes, program, "-o", scratch / "probe", *libraries,
         *system_libs, "-ldl", "-lpthread"], scratch, timeout=900)
    return scratch / "probe"


PROBE = r'''
#include "core/wire/codec.h"
#include "system/haptics_system.h"
#include "system/renderer_registry.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

using namespace haptics;

static std::vector<uint8_t> read_file(const char *p_path) {
	std::ifstream in(p_path, std::ios::binary);
	return { std::istreambuf_iterator<char>(in), {} };
}

int main(int argc, char **argv) {
	if (argc == 3 && std::strcmp(argv[1], "decode") == 0) {
		Frame frame;
		const Status status = decode(read_file(argv[2]), frame);
		if (!status) {
			std::printf("refused: %s\n", status.message());
			return 1;
		}
		std::printf("grip %.3f of %zu contacts\n", frame.contacts[0].grip_n, frame.contacts.size());
		frame.contacts[0].grip_n = 4.5;
		const std::vector<uint8_t> bytes = encode(frame);
		std::ofstream(argv[2], std::ios::binary).write(reinterpret_cast<const char *>(bytes.data()), bytes.size());
		return 0;
	}
	Frame frame;
	frame.contacts.push_back(Contact{});
	frame.contacts[0].normal = { 0.0, 1.0, 0.0 };
	frame.contacts[0].grip_n = 7.0;
	std::printf("out of range: %s\n", check_fields(frame).message());
	HapticsSystem system;
	for (const RegisteredRenderer &renderer : registered_renderers()) {
		std::printf("renderer %s\n", renderer.name);
	}
	if (!system.open_simulated_device(SimulatedDeviceConfig{})) {
		return 2;
	}
	system.set_hand_target({ 0.02, 0.0, 0.0 });
	RenderConfig config = system.config();
	config.servo.render_mode = RENDER_MODE_COUNT - 1;
	config.servo.safety.startup_ramp_s = 0.0;
	config.servo.safety.slew_rate_n_per_s = 0.0;
	config.spring.stiffness_n_per_m = 100.0;
	if (!system.configure(config)) {
		return 3;
	}
	for (int tick = 0; tick < 500; ++tick) {
		system.step(0.001);
	}
	const ForceComponents forces = system.forces();
	std::printf("spring pull %.4f at %.4f m\n", forces.parts[0].x, system.device_position().x);
	config.spring.stiffness_n_per_m = -1.0;
	std::printf("bad spring: %s\n", system.configure(config).message());
	return 0;
}
'''


def test_the_field_and_the_new_renderer_work_in_cpp(built):
    out = run([built], built.parent).stdout
    assert "out of range: HapticFrame.contacts[0].grip_n: 7 is outside [0, 5]" in out, out
    names = re.findall(r"^renderer (\w+)$", out, re.M)
    assert names == ["movement", "constraint", "pong", "vehicle", "spring"], out
    pull, position = map(float, re.search(r"spring pull (\S+) at (\S+) m", out).groups())
    assert position > 0.005, out
    assert pull == pytest.approx(-100.0 * position, rel=0.05), out
    assert "bad spring: SpringSettings.stiffness_n_per_m: -1 is outside [0, 500]" in out, out


def _godot(scratch, *args, check=True):
    return run([scratch / "tools/godot", "--headless", "--path", scratch, *args], scratch, check=check)


def test_gdscript_has_the_field_typed_and_a_misspelling_does_not_parse(scratch, built):
    _godot(scratch, "--import")
    (scratch / "roundtrip.gd").write_text(textwrap.dedent('''\
        extends SceneTree


        func _init() -> void:
        \tvar contact: HapticContact = HapticContact.new()
        \tcontact.normal = Vector2.UP
        \tcontact.grip_n = 1.5
        \tvar frame: HapticFrame = HapticFrame.new()
        \tframe.contacts = [contact]
        \tvar path: String = OS.get_environment("FRAME_FILE")
        \tif OS.get_environment("READ") == "1":
        \t\tvar back: HapticFrame = HapticFrame.decode(FileAccess.get_file_as_bytes(path))
        \t\tprint("gdscript read grip %.3f" % back.contacts[0].grip_n)
        \t\tcontact.grip_n = 9.0
        \t\tprint("gdscript refuses: ", HapticFrame.decode(frame.encode()) == null, " ", HapticsWireReader.last_error)
        \telse:
        \t\tvar file: FileAccess = FileAccess.open(path, FileAccess.WRITE)
        \t\tfile.store_buffer(frame.encode())
        \t\tfile.close()
        \tquit()
        '''))
    frame_file = scratch / "frame.bin"
    env = dict(os.environ, FRAME_FILE=str(frame_file))
    subprocess.run([scratch / "tools/godot", "--headless", "--path", scratch, "-s", "res://roundtrip.gd"],
                   cwd=scratch, env=env, check=True, capture_output=True, timeout=600)
    assert "grip 1.500 of 1 contacts" in run([built, "decode", frame_file], scratch).stdout
    env["READ"] = "1"
    out = subprocess.run([scratch / "tools/godot", "--headless", "--path", scratch, "-s", "res://roundtrip.gd"],
                         cwd=scratch, env=env, capture_output=True, text=True, timeout=600).stdout
    assert "gdscript read grip 4.500" in out, out
    assert "gdscript refuses: true HapticFrame.contacts[0].grip_n" in out, out
    (scratch / "misspelt.gd").write_text(
        "extends RefCounted\n\n\nfunc touch(contact: HapticContact) -> void:\n\tcontact.grip_nn = 1.0\n")
    misspelt = _godot(scratch, "--check-only", "-s", "res://misspelt.gd", check=False)
    assert misspelt.returncode != 0
    assert "grip_nn" in misspelt.stdout + misspelt.stderr
    (scratch / "spring_use.gd").write_text(
        "extends RefCounted\n\n\nfunc k(settings: SpringSettings) -> float:\n"
        "\treturn settings.stiffness_n_per_m + SpringFacts.SpringForce.PULL\n")
    assert _godot(scratch, "--check-only", "-s", "res://spring_use.gd", check=False).returncode == 0
