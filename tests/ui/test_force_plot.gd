extends TestSuite
## The |F| plot's ring buffer keeps the last N samples in order without reallocating, and
## the plot samples at a fixed rate whatever the frame rate, keeping short peaks.


func test_the_ring_keeps_the_last_n_samples_oldest_first() -> void:
	var ring: RingBuffer = RingBuffer.new(5)
	for i: int in 3:
		ring.push(float(i))
	assert_eq(ring.size(), 3)
	assert_eq(ring.to_array(), PackedFloat32Array([0.0, 1.0, 2.0]))
	for i: int in range(3, 12):
		ring.push(float(i))
	assert_eq(ring.size(), 5)
	assert_eq(ring.capacity, 5)
	assert_eq(ring.to_array(), PackedFloat32Array([7.0, 8.0, 9.0, 10.0, 11.0]))
	assert_eq(ring.get_value(0), 7.0)
	assert_eq(ring.last(), 11.0)
	assert_eq(ring.max_value(), 11.0)
	assert_eq(ring.get_value(5), 0.0, "out of range reads zero")


func test_clear_forgets_but_keeps_the_capacity() -> void:
	var ring: RingBuffer = RingBuffer.new(4)
	for i: int in 10:
		ring.push(1.0)
	ring.clear()
	assert_true(ring.is_empty())
	assert_eq(ring.capacity, 4)
	ring.push(3.0)
	assert_eq(ring.to_array(), PackedFloat32Array([3.0]))


func test_the_plot_holds_five_seconds_at_its_sample_rate() -> void:
	var plot: ForcePlot = add_child_autofree(ForcePlot.new()) as ForcePlot
	assert_eq(plot.get_capacity(), 300, "5 s at 60 Hz")
	for frame: int in 600:
		plot.advance(1.0 / 60.0, float(frame))
	assert_eq(plot.buffer.size(), 300)
	assert_eq(plot.buffer.capacity, 300)
	assert_almost_eq(plot.buffer.last(), 599.0, 1.0)
	assert_almost_eq(plot.buffer.get_value(0), 300.0, 1.0)


func test_the_plot_samples_by_time_not_by_frame() -> void:
	var plot: ForcePlot = add_child_autofree(ForcePlot.new()) as ForcePlot
	plot.advance(0.5, 1.0)
	assert_eq(plot.buffer.size(), 30, "half a second at 60 Hz")
	for frame: int in 144:
		plot.advance(1.0 / 144.0, 1.0)
	assert_almost_eq(float(plot.buffer.size()), 90.0, 1.0, "one more second")


func test_a_short_peak_between_samples_is_kept() -> void:
	var plot: ForcePlot = add_child_autofree(ForcePlot.new()) as ForcePlot
	plot.advance(0.002, 2.5)
	plot.advance(1.0 / 60.0, 0.0)
	assert_eq(plot.buffer.last(), 2.5)
	plot.advance(1.0 / 60.0, 0.0)
	assert_eq(plot.buffer.last(), 0.0)
