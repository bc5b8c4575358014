# gdlint: disable=max-public-methods
extends "res://addons/haptics/door/haptics_backend.gd"
## The native library behind the [code]Haptics[/code] door: the base's every method,
## answered by a [code]HapticsServer[/code] of its own. The door loads this script by its
## path, and only when [code]ClassDB[/code] has that class: it is the one script that names
## it. Values cross as their schema's bytes ([code]encode()[/code], [code]decode()[/code]);
## bytes this script cannot decode mean the library and the addon's scripts are of different
## versions, which is reported once.

var _server: HapticsServer = HapticsServer.new()
var _reported_mismatch: bool = false


func is_native() -> bool:
	return true


func version() -> String:
	return _server.get_version()


func list_devices() -> HapticDeviceList:
	var value: HapticDeviceList = HapticDeviceList.decode(_server.list_devices())
	if value == null:
		_out_of_step()
		value = HapticDeviceList.new()
	return value


func simulated_device_id() -> String:
	return _server.get_simulated_device_id()


func open_device(id: String) -> bool:
	return _server.open_device(id)


func close_device() -> void:
	_server.close_device()


func device_id() -> String:
	return _server.get_device_id()


func device_name() -> String:
	return _server.get_device_name()


func device_capabilities() -> HapticDeviceCapabilities:
	var value: HapticDeviceCapabilities = HapticDeviceCapabilities.decode(
		_server.get_device_capabilities()
	)
	if value == null:
		_out_of_step()
		value = HapticDeviceCapabilities.new()
	return value


func device_status() -> HapticDeviceStatus:
	var value: HapticDeviceStatus = HapticDeviceStatus.decode(_server.get_device_status())
	if value == null:
		_out_of_step()
		value = HapticDeviceStatus.new()
	return value


func calibrate() -> bool:
	return _server.calibrate()


func set_hand_target(target_m: Vector3) -> bool:
	return _server.set_hand_target(target_m)


func hand_target() -> Vector3:
	return _server.get_hand_target()


func set_simulated_plugged(plugged: bool) -> bool:
	return _server.set_simulated_plugged(plugged)


func start(rate_hz: float, spin_us: float) -> bool:
	return _server.start(rate_hz, spin_us)


func stop() -> void:
	_server.stop()


func is_running() -> bool:
	return _server.is_running()


func step(dt: float) -> bool:
	return _server.step(dt)


func servo_status() -> String:
	return _server.get_servo_status()


func submit_frame(frame: HapticFrame) -> bool:
	return _server.submit_frame(frame.encode())


func push_impact(impact: HapticImpact) -> bool:
	return _server.push_impact(impact.encode())


func input_vector() -> Vector2:
	return _server.get_input_vector()


func device_position() -> Vector2:
	return _server.get_device_position()


func forces() -> HapticForces:
	var value: HapticForces = HapticForces.decode(_server.get_forces())
	if value == null:
		_out_of_step()
		value = HapticForces.new()
	return value


func stats() -> HapticServoStats:
	var value: HapticServoStats = HapticServoStats.decode(_server.get_stats())
	if value == null:
		_out_of_step()
		value = HapticServoStats.new()
	return value


func drain_telemetry(max_samples: int) -> PackedFloat32Array:
	return _server.drain_telemetry(max_samples)


func telemetry_columns() -> PackedStringArray:
	return _server.get_telemetry_columns()


func renderer_names() -> PackedStringArray:
	return _server.get_renderer_names()


func set_render_mode(mode: int) -> bool:
	return _server.set_render_mode(mode)


func render_mode() -> int:
	return _server.get_render_mode()


func set_config(section: String, values: Dictionary) -> bool:
	return _server.set_config(section, values)


func get_config() -> Dictionary:
	return _server.get_config()


func get_config_fields() -> Array:
	return _server.get_config_fields()


func renderer_send(mode: int, message: PackedByteArray) -> bool:
	return _server.renderer_send(mode, message)


func renderer_read(mode: int, value_id: int) -> PackedByteArray:
	return _server.renderer_read(mode, value_id)


func _out_of_step() -> void:
	if not _reported_mismatch:
		_reported_mismatch = true
		push_error(
			(
				"Haptics: the native library and the addon's scripts are of different versions "
				+ "(%s); reinstall the addon whole." % HapticsWireReader.last_error
			)
		)
