# gdlint: disable=max-public-methods
extends RefCounted
## What the [code]Haptics[/code] door asks of the native library, typed. This base answers
## as a game without the library plays: nothing present, nothing rendered, neutral values.
## The door loads the native backend ([code]haptics_native_backend.gd[/code]), which
## overrides every method, only once the library has registered [code]HapticsSystem[/code]:
## that script is the only one that names the native class, so every other script parses
## where the library cannot load (an unsupported platform, a project before its first build).
##
## Values cross as the schema classes (addons/haptics/values, docs/values.md).


## Whether the native library answers (false here).
func is_native() -> bool:
	return false


func version() -> String:
	return "haptics extension not loaded"


func list_devices() -> HapticDeviceList:
	return HapticDeviceList.new()


func simulated_device_id() -> String:
	return ""


## [param _options]: what the open may change on the device (its gain, its centring spring).
func open_device(_id: String, _options: HapticDeviceOpenOptions) -> bool:
	return false


func close_device() -> void:
	pass


func device_id() -> String:
	return ""


func device_name() -> String:
	return ""


func device_capabilities() -> HapticDeviceCapabilities:
	return HapticDeviceCapabilities.new()


func device_status() -> HapticDeviceStatus:
	return HapticDeviceStatus.new()


func calibrate() -> bool:
	return false


## The simulated hand's target, device space (x right, y up, z toward the user), metres.
func set_hand_target(_target_m: Vector3) -> bool:
	return false


func hand_target() -> Vector3:
	return Vector3.ZERO


func set_simulated_plugged(_plugged: bool) -> bool:
	return false


func start(_rate_hz: float, _spin_us: float) -> bool:
	return false


func stop() -> void:
	pass


func is_running() -> bool:
	return false


func step(_dt: float) -> bool:
	return false


func servo_status() -> String:
	return ""


func submit_frame(_frame: HapticFrame) -> bool:
	return false


func push_impact(_impact: HapticImpact) -> bool:
	return false


func submit_frame_3d(_frame: HapticFrame3D) -> bool:
	return false


func push_impact_3d(_impact: HapticImpact3D) -> bool:
	return false


## Game axes, length at most 1.
func input_vector() -> Vector2:
	return Vector2.ZERO


## Game axes, metres.
func device_position() -> Vector2:
	return Vector2.ZERO


func forces() -> HapticForces:
	return HapticForces.new()


## A 3D game's view axes (x right, y up, z toward the viewer), length at most 1.
func input_vector_3d() -> Vector3:
	return Vector3.ZERO


func forces_3d() -> HapticForces3D:
	return HapticForces3D.new()


func stats() -> HapticServoStats:
	return HapticServoStats.new()


func drain_telemetry(_max_samples: int) -> PackedFloat32Array:
	return PackedFloat32Array()


func telemetry_columns() -> PackedStringArray:
	return PackedStringArray()


## The renderers by name, in render-mode order.
func renderer_names() -> PackedStringArray:
	return PackedStringArray()


func set_render_mode(_mode: int) -> bool:
	return false


## -1 without the library.
func render_mode() -> int:
	return -1


## The servo's settings (the defaults here); a copy, the caller may change it.
func servo_settings() -> HapticServoSettings:
	return HapticServoSettings.new()


## Hands the servo [param _settings] whole; refused ones are reported and change nothing.
func set_servo_settings(_settings: HapticServoSettings) -> bool:
	return false


## The bytes of renderer [param mode]'s settings (its own schema's value).
func renderer_settings(_mode: int) -> PackedByteArray:
	return PackedByteArray()


## Hands renderer [param mode] its settings whole, as its schema's value.
func set_renderer_settings(_mode: int, _settings: HapticsValue) -> bool:
	return false


## Hands renderer [param mode] a value of its own schema (its bytes).
func renderer_send(_mode: int, _message: PackedByteArray) -> bool:
	return false


## The bytes of the value of layout [param value_id] renderer [param mode] gives.
func renderer_read(_mode: int, _value_id: int) -> PackedByteArray:
	return PackedByteArray()
