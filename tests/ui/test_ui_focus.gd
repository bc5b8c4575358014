extends TestSuite
## UiFocus.grab_later: the focus moves at the end of the frame, and only to a control that is
## still there then. Screens are swapped within a frame, so a control may be freed, or taken
## out of the tree, between the call and the end of the frame.


func test_a_control_in_the_tree_takes_the_focus_at_the_end_of_the_frame() -> void:
	var button: Button = add_child_autofree(Button.new()) as Button
	UiFocus.grab_later(button)
	assert_false(button.has_focus(), "not before the frame ends")
	await wait_process_frames(2)
	assert_true(button.has_focus())


func test_a_control_freed_before_the_frame_ends_is_skipped_without_an_error() -> void:
	var keeper: Button = add_child_autofree(Button.new()) as Button
	keeper.grab_focus()
	var doomed: Button = Button.new()
	add_child(doomed)
	UiFocus.grab_later(doomed)
	doomed.free()
	# The runner fails a test on any engine error: a freed Control handed to the deferred
	# call was one ("Cannot convert argument 1 from Object to Object").
	await wait_process_frames(2)
	assert_true(keeper.has_focus(), "the focus stayed where it was")


func test_a_control_taken_out_of_the_tree_does_not_take_the_focus() -> void:
	var keeper: Button = add_child_autofree(Button.new()) as Button
	keeper.grab_focus()
	var removed: Button = autofree(Button.new()) as Button
	add_child(removed)
	UiFocus.grab_later(removed)
	remove_child(removed)
	await wait_process_frames(2)
	assert_true(keeper.has_focus())
	assert_false(removed.has_focus())
