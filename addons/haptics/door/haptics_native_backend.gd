# gdlint: disable=max-public-methods
extends "res://addons/haptics/door/haptics_backend.gd"
## The native library behind the [code]Haptics[/code] door: the base's every method,
## answered by a [code]HapticsSystem[/code] of its own. The door loads this script by its
## path, and only when [code]ClassDB[/code] has that class: it is the one script that names
## it. Values cross as their schema's bytes ([code]encode()[/code], [code]decode()[/code]);
## bytes this script cannot decode mean the library and the addon's scripts are of different
## versions, which is reported once.

var _native: HapticsSystem = HapticsSystem.new()
var _reported_mismatch: bool = false


func is_native() -> bool:
	return true


func version() -> String:
	return _native.get_version()


func list_devices() -> HapticDeviceList:
	var value: HapticDeviceList = HapticDeviceList.decode(_native.list_devices())
	if value == null:
		_out_of_step()
		value = HapticDeviceList.new()
	return value


func simulated_device_id() -> String:
	return _native.get_simulated_device_id()


func open_device(id: String, options: HapticDeviceOpenOptions) -> bool:
	return _native.set_device_open_options(options.encode()) and _native.open_device(id)


func close_device() -> void:
	_native.close_device()


func device_id() -> String:
	return _native.get_device_id()


func device_name() -> String:
	return _native.get_device_name()


func device_capabilities() -> HapticDeviceCapabilities:
	var value: HapticDeviceCapabilities = HapticDeviceCapabilities.decode(
		_native.get_device_capabilities()
	)
	if value == null:
		_out_of_step()
		value = HapticDeviceCapabilities.new()
	return value


func device_status() -> HapticDeviceStatus:
	var value: HapticDeviceStatus = HapticDeviceStatus.decode(_native.get_device_status())
	if value == null:
		_out_of_step()
		value = HapticDeviceStatus.new()
	return value


func calibrate() -> bool:
	return _native.calibrate()


func set_hand_target(target_m: Vector3) -> bool:
	return _native.set_hand_target(target_m)


func hand_target() -> Vector3:
	return _native.get_hand_target()


func set_simulated_plugged(plugged: bool) -> bool:
	return _native.set_simulated_plugged(plugged)


func start(rate_hz: float, spin_us: float) -> bool:
	return _native.start(rate_hz, spin_us)


func stop() -> void:
	_native.stop()


func is_running() -> bool:
	return _native.is_running()


func step(dt: float) -> bool:
	return _native.step(dt)


func servo_status() -> String:
	return _native.get_servo_status()


func submit_frame(frame: HapticFrame) -> bool:
	return _native.submit_frame(frame.encode())


func push_impact(impact: HapticImpact) -> bool:
	return _native.push_impact(impact.encode())


func submit_frame_3d(frame: HapticFrame3D) -> bool:
	return _native.submit_frame(frame.encode())


func push_impact_3d(impact: HapticImpact3D) -> bool:
	return _native.push_impact(impact.encode())


func input_vector() -> Vector2:
	return _native.get_input_vector()


func device_position() -> Vector2:
	return _native.get_device_position()


func forces() -> HapticForces:
	var value: HapticForces = HapticForces.decode(_native.get_forces())
	if value == null:
		_out_of_step()
		value = HapticForces.new()
	return value


func input_vector_3d() -> Vector3:
	return _native.get_input_vector_3d()


func forces_3d() -> HapticForces3D:
	var value: HapticForces3D = HapticForces3D.decode(_native.get_forces_3d())
	if value == null:
		_out_of_step()
		value = HapticForces3D.new()
	return value


func stats() -> HapticServoStats:
	var value: HapticServoStats = HapticServoStats.decode(_native.get_stats())
	if value == null:
		_out_of_step()
		value = HapticServoStats.new()
	return value


func drain_telemetry(max_samples: int) -> PackedFloat32Array:
	return _native.drain_telemetry(max_samples)


func telemetry_columns() -> PackedStringArray:
	return _native.get_telemetry_columns()


func renderer_names() -> PackedStringArray:
	return _native.get_renderer_names()


func set_render_mode(mode: int) -> bool:
	return _native.set_render_mode(mode)


func render_mode() -> int:
	return _native.get_render_mode()


func servo_settings() -> HapticServoSettings:
	var value: HapticServoSettings = HapticServoSettings.decode(_native.get_servo_settings())
	if value == null:
		_out_of_step()
		value = HapticServoSettings.new()
	return value


func set_servo_settings(settings: HapticServoSettings) -> bool:
	return _native.set_servo_settings(settings.encode())


func renderer_settings(mode: int) -> PackedByteArray:
	return _native.get_renderer_settings(mode)


func set_renderer_settings(mode: int, settings: HapticsValue) -> bool:
	return _native.set_renderer_settings(mode, settings.encode())


func renderer_send(mode: int, message: PackedByteArray) -> bool:
	return _native.renderer_send(mode, message)


func renderer_read(mode: int, value_id: int) -> PackedByteArray:
	return _native.renderer_read(mode, value_id)


func _out_of_step() -> void:
	if not _reported_mismatch:
		_reported_mismatch = true
		push_error(
			(
				"Haptics: the native library and the addon's scripts are of different versions "
				+ "(%s); reinstall the addon whole." % HapticsWireReader.last_error
			)
		)
