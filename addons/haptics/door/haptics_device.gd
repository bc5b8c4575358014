class_name HapticsDevice
extends RefCounted
## The device side of the [code]Haptics[/code] door ([code]Haptics.device[/code]): the devices
## present, the open one, its limits, and the simulated device's hand. Positions are
## normalised (fractions of the workspace radius, game axes); without the native extension
## every answer is neutral.

## The open device changed.
signal changed

## Seconds between attempts to reopen a device that was unplugged.
const RECONNECT_INTERVAL_S := 2.0

var _server: Object = null
var _servo: HapticsServo = null
var _reconnect_countdown: float = 0.0


func _init(server: Object, servo: HapticsServo) -> void:
	_server = server
	_servo = servo


## Every device present (the simulated one first), each a [Dictionary] (id, model,
## known_haptic, driver, openable, unavailable_reason…); empty without the extension.
func list_present() -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	if _server != null:
		out.assign(_server.call(&"list_devices"))
	return out


## The id of the simulated device every installation has ("" without the extension).
func get_simulated_id() -> String:
	return str(_server.call(&"get_simulated_device_id")) if _server != null else ""


## Opens the device with this id and keeps rendering if the servo was. On failure the
## current device stays open.
func open(id: String) -> bool:
	if _server == null:
		return false
	var was_running: bool = _servo.is_running()
	var opened: bool = _server.call(&"open_device", id)
	if opened and was_running:
		_servo.start()
	changed.emit()
	return opened


## Id of the open device ("" when none).
func get_id() -> String:
	return str(_server.call(&"get_device_id")) if _server != null else ""


## Name of the open device ("" when none).
func get_name() -> String:
	return str(_server.call(&"get_device_name")) if _server != null else ""


## True when the open device is the simulated one (its hand can be moved).
func is_simulated() -> bool:
	return _server != null and get_id() == get_simulated_id()


## What the open device can feel and render (input_dof, output, native_rate_hz…; layout:
## HapticsServer.get_device_capabilities); empty without a device.
func get_capabilities() -> Dictionary:
	return _server.call(&"get_device_capabilities") if _server != null else {}


## The open device's own account of a fault: [code]{io, reason}[/code] with io
## [code]"ok"[/code], [code]"disconnected"[/code] or [code]"failed"[/code].
func get_status() -> Dictionary:
	return _server.call(&"get_device_status") if _server != null else {"io": "ok", "reason": ""}


## True while the open device has stopped rendering on its own (unplugged, I/O error):
## the servo wrote zero force and the game plays on the keyboard until it is back.
func is_lost() -> bool:
	return _server != null and not _servo.get_status().is_empty()


## Called every frame by [code]Haptics[/code]: reopens a lost physical device once it is
## listed as openable again (replugged), and restarts rendering. The simulated device's
## cable is its own and comes back only with HapticsServer.set_simulated_plugged.
func poll_reconnect(delta: float) -> void:
	if not is_lost() or is_simulated():
		_reconnect_countdown = 0.0
		return
	_reconnect_countdown -= delta
	if _reconnect_countdown > 0.0:
		return
	_reconnect_countdown = RECONNECT_INTERVAL_S
	var id: String = get_id()
	for present: Dictionary in list_present():
		if str(present.get("id", "")) == id and present.get("openable", false) == true:
			if open(id):
				_servo.start()
			return


## The open device's force limit in newtons (0 without a device).
func get_max_force() -> float:
	return _limit("max_force_n")


## The open device's workspace radius in metres (0 without a device).
func get_workspace_radius() -> float:
	return _limit("workspace_radius_m")


## The open device's position, normalised.
func get_position() -> Vector2:
	return _normalised(&"get_device_position")


## Moves the simulated device's hand to a normalised workspace position.
func set_hand_target(normalised: Vector2) -> void:
	var radius: float = get_workspace_radius()
	if radius > 0.0:
		_server.call(&"set_hand_target", normalised.limit_length(1.0) * radius)


## The simulated hand's target, normalised.
func get_hand_target() -> Vector2:
	return _normalised(&"get_hand_target")


func _limit(key: String) -> float:
	if _server == null:
		return 0.0
	var limits: Dictionary = _server.call(&"get_device_limits")
	return float(limits.get(key, 0.0))


func _normalised(method: StringName) -> Vector2:
	var radius: float = get_workspace_radius()
	if radius <= 0.0:
		return Vector2.ZERO
	var metres: Vector2 = _server.call(method)
	return metres / radius
