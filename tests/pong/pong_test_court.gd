extends RefCounted
## A court for the unit tests of the pure Pong classes: the settings' schema defaults with
## the test's [param overrides] (no servo needed; the scene tests use the servo's).


static func make(overrides: Dictionary = {}) -> PongCourt:
	var settings: PongSettings = PongSettings.new()
	for key: String in overrides:
		assert(key in settings, "PongSettings has no %s" % key)
		settings.set(key, overrides[key])
	return PongCourt.from_settings(settings)
