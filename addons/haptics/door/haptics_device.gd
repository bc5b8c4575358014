class_name HapticsDevice
extends RefCounted
## The device side of the [code]Haptics[/code] door ([code]Haptics.device[/code]): the devices
## present, the open one, its limits, and the simulated device's hand. Positions are
## normalised (fractions of the workspace radius, game axes) unless named otherwise; without
## the native extension every answer is neutral.

## The open device changed.
signal changed

## Seconds between attempts to reopen a device that was unplugged.
const RECONNECT_INTERVAL_S := 2.0
const HapticsBackend := preload("res://addons/haptics/door/haptics_backend.gd")

var _backend: HapticsBackend = null
var _servo: HapticsServo = null
var _reconnect_countdown: float = 0.0
# The options of the last open: a replugged device is opened again with them.
var _options: HapticDeviceOpenOptions = null
# Whether the servo rendered when the device was closed: the next open renders again (a game
# that reopens its device with other options keeps its forces and its simulated hand).
var _rendered_at_close: bool = false
var _warnings: PackedStringArray = PackedStringArray()


func _init(backend: HapticsBackend, servo: HapticsServo) -> void:
	_backend = backend
	_servo = servo


## Every device present, the simulated one first (empty without the extension); also
## refreshes [method get_warnings].
func list_present() -> Array[HapticDeviceInfo]:
	var list: HapticDeviceList = _backend.list_devices()
	_warnings = list.warnings
	return list.devices


## Why the last [method list_present] could not look everywhere (no USB bus, no
## permission...).
func get_warnings() -> PackedStringArray:
	return _warnings


## The id of the simulated device every installation has ("" without the extension).
func get_simulated_id() -> String:
	return _backend.simulated_device_id()


## Opens the device with this id and keeps rendering if the servo was (or was when
## [method close] closed the last device). On failure the current device stays open.
## [param options] says what the open may change on the device (null: the defaults: the
## player's gain left alone, the centring spring turned off).
func open(id: String, options: HapticDeviceOpenOptions = null) -> bool:
	if not _backend.is_native():
		return false
	var was_running: bool = _servo.is_running() or _rendered_at_close
	var asked: HapticDeviceOpenOptions = (
		options if options != null else HapticDeviceOpenOptions.new()
	)
	var opened: bool = _backend.open_device(id, asked)
	if opened:
		_options = asked
		_rendered_at_close = false
	if opened and was_running:
		_servo.start()
	changed.emit()
	return opened


## Closes the open device (zero force first); the next [method open] renders again if the
## servo rendered now.
func close() -> void:
	_rendered_at_close = _rendered_at_close or _servo.is_running()
	_backend.close_device()
	changed.emit()


## Id of the open device ("" when none).
func get_id() -> String:
	return _backend.device_id()


## Name of the open device ("" when none).
func get_name() -> String:
	return _backend.device_name()


## True when the open device is the simulated one (its hand can be moved).
func is_simulated() -> bool:
	return _backend.is_native() and get_id() == get_simulated_id()


## What the open device can feel and render (its limits inside; zero limits without one).
func get_capabilities() -> HapticDeviceCapabilities:
	return _backend.device_capabilities()


## The open device's own account of a fault.
func get_status() -> HapticDeviceStatus:
	return _backend.device_status()


## True while the open device has stopped rendering on its own (unplugged, I/O error):
## the servo wrote zero force and the game plays on the keyboard until it is back.
func is_lost() -> bool:
	return _backend.is_native() and not _servo.get_status().is_empty()


## Called every frame by [code]Haptics[/code]: reopens a lost physical device once it is
## listed as openable again (replugged), and restarts rendering. The simulated device's
## cable is its own and comes back only with [method set_simulated_plugged].
func poll_reconnect(delta: float) -> void:
	if not is_lost() or is_simulated():
		_reconnect_countdown = 0.0
		return
	_reconnect_countdown -= delta
	if _reconnect_countdown > 0.0:
		return
	_reconnect_countdown = RECONNECT_INTERVAL_S
	var id: String = get_id()
	for present: HapticDeviceInfo in list_present():
		if present.id == id and present.openable:
			if open(id, _options):
				_servo.start()
			return


## Unplugs ([code]false[/code]) or replugs a device made in software (the simulated one, the
## development builds' device models), to exercise what a player meets when a cable is
## pulled.
func set_simulated_plugged(plugged: bool) -> bool:
	return _backend.set_simulated_plugged(plugged)


## Calibrates the open device (not while rendering).
func calibrate() -> bool:
	return _backend.calibrate()


## The open device's force limit in newtons (0 without a device).
func get_max_force() -> float:
	return get_capabilities().limits.max_force_n


## The open device's workspace radius in metres (0 without a device).
func get_workspace_radius() -> float:
	return get_capabilities().limits.workspace_radius_m


## The open device's position, normalised.
func get_position() -> Vector2:
	var radius: float = get_workspace_radius()
	return _backend.device_position() / radius if radius > 0.0 else Vector2.ZERO


## Moves the simulated device's hand to a normalised workspace position (game axes).
func set_hand_target(normalised: Vector2) -> void:
	var radius: float = get_workspace_radius()
	if radius > 0.0:
		var target: Vector2 = normalised.limit_length(1.0) * radius
		_backend.set_hand_target(Vector3(target.x, -target.y, 0.0))


## The simulated hand's target, normalised (game axes).
func get_hand_target() -> Vector2:
	var radius: float = get_workspace_radius()
	var target: Vector3 = _backend.hand_target()
	return Vector2(target.x, -target.y) / radius if radius > 0.0 else Vector2.ZERO


## Moves the simulated device's hand to [param target_m] in device space (metres: x right,
## y up, z toward the user), kept within the workspace radius: a 3D game moves the stylus in
## depth too.
func set_hand_target_3d(target_m: Vector3) -> bool:
	return _backend.set_hand_target(target_m.limit_length(get_workspace_radius()))
