extends TestSuite
## The base of the suites that open a Pong screen: [member _pong] (a test's screen, or null)
## is freed after each test, and two frames let its servo session close before the next.

var _pong: PongScreen = null


func after_each() -> void:
	await _free_pong()


## Frees [member _pong] and waits for it to go.
func _free_pong() -> void:
	if _pong != null and is_instance_valid(_pong):
		_pong.queue_free()
	_pong = null
	# A winner screen freed while it showed leaves the tree paused: no later suite's input
	# would reach its match.
	get_tree().paused = false
	await wait_process_frames(2)


## Waits, as a person does, until [param pong]'s setup offers its buttons (the court behind
## it drawn); false if it never does.
func _setup_offered(pong: PongScreen) -> bool:
	return await wait_until(func() -> bool: return not pong.setup.is_preparing(), 5.0)
