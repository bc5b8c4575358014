extends RefCounted
## The test runner's command-line options (see runner.gd for what each one does).

## Printed by --help.
const USAGE: String = """\
usage: tools/godot --headless --path . res://tests/runner/runner.tscn -- [options]
  --dir=PATH            folder or test_*.gd file to run (repeatable; default res://tests)
  --filter=TEXT         only files whose path contains TEXT (repeatable)
  --test=TEXT           only tests whose name or suite::test contains TEXT (repeatable)
  --timeout=SECONDS     timeout of each hook and each test (default 30)
  --junit=PATH          also write JUnit XML
  --warnings-as-errors  GDScript warnings enabled in the project fail a suite's load
  --quick               leave out the suites that declare const SLOW := true
  --shard=K/N           only every Nth test file, from the Kth (two runners share a machine)
  --help                print this help"""
const DEFAULT_ROOT: String = "res://tests"
const DEFAULT_TIMEOUT_SECONDS: float = 30.0
const RunnerOptions := preload("res://tests/runner/options.gd")

## Folders or files to search.
var roots: PackedStringArray = PackedStringArray()
## Path substrings; empty means every file.
var file_filters: PackedStringArray = PackedStringArray()
## Test name substrings; empty means every test.
var test_filters: PackedStringArray = PackedStringArray()
## Default timeout of each phase, in seconds.
var timeout_seconds: float = DEFAULT_TIMEOUT_SECONDS
## Where to write JUnit XML; empty for none.
var junit_path: String = ""
## Whether enabled GDScript warnings become errors while suites load.
var warnings_as_errors: bool = false
## Whether suites declaring [code]const SLOW := true[/code] are left out.
var quick: bool = false
## This runner's share of the files, [member shard] of [member shards] (1-based): every
## [member shards]th file of the sorted list, from the [member shard]th.
var shard: int = 1
var shards: int = 1
## Whether --help was given.
var help: bool = false
## Why the options are invalid; empty when they are fine.
var error: String = ""


## The options in [param args] (the engine's user arguments); [member error] says what is wrong.
static func parse(args: PackedStringArray) -> RunnerOptions:
	var options: RunnerOptions = RunnerOptions.new()
	for arg: String in args:
		var key: String = arg.get_slice("=", 0)
		var value: String = arg.substr(key.length() + 1) if arg.contains("=") else ""
		match key:
			"--dir":
				options.roots.append(_normalize_dir(value))
			"--filter":
				options.file_filters.append(value)
			"--test":
				options.test_filters.append(value)
			"--timeout":
				if not value.is_valid_float() or value.to_float() <= 0.0:
					options.error = "--timeout needs a positive number of seconds"
				options.timeout_seconds = value.to_float()
			"--junit":
				options.junit_path = value
			"--warnings-as-errors":
				options.warnings_as_errors = true
			"--quick":
				options.quick = true
			"--shard":
				var parts: PackedStringArray = value.split("/")
				if (
					parts.size() != 2
					or not parts[0].is_valid_int()
					or not parts[1].is_valid_int()
					or parts[0].to_int() < 1
					or parts[0].to_int() > parts[1].to_int()
				):
					options.error = "--shard needs K/N with 1 <= K <= N (--shard=1/2)"
				else:
					options.shard = parts[0].to_int()
					options.shards = parts[1].to_int()
			"--help", "-h":
				options.help = true
			_:
				options.error = "unknown option " + arg
		if (key in ["--dir", "--filter", "--test", "--junit", "--shard"]) and value.is_empty():
			options.error = "%s needs a value (%s=...)" % [key, key]
	if options.roots.is_empty():
		options.roots.append(DEFAULT_ROOT)
	return options


static func _normalize_dir(path: String) -> String:
	var normalized: String = path.strip_edges()
	while normalized.length() > 1 and normalized.ends_with("/") and not normalized.ends_with("://"):
		normalized = normalized.left(-1)
	return normalized
