class_name PongView
extends Node3D
## The 3D picture of a match, redrawn every frame from the newest servo state (the ball
## and paddles are the servo's; nothing here moves them): the court, a camera behind and
## above the near player, the ball with its blob shadow and drop line, both avatars and
## paddles, the mines and the bullets. The ball casts no shadow from the sun: its one
## shadow is the blob straight below it, the cue for where it is (the sun's would fall
## to the side). Physics interpolation is off for the whole view:
## the servo, not Godot's physics, moves these things.

## The preview's last thing was drawn this frame: after it, no first frame stalls.
signal previewed

const PLAYER_COLORS: Array[Color] = [
	Color(0.25, 0.75, 1.0), Color(1.0, 0.5, 0.2), Color(0.35, 0.9, 0.4), Color(0.85, 0.45, 1.0)
]
## Growth of the blob shadow per metre of height, and the height at which it has faded to
## its faintest.
const SHADOW_GROWTH_PER_M: float = 0.6
const SHADOW_FADE_HEIGHT_M: float = 2.5
const SHADOW_MIN_ALPHA: float = 0.35
## Bullets are hot red streaks along their flight, the length of [constant BULLET_LENGTH_M]:
## never mistaken for the round ball.
const BULLET_COLOR: Color = Color(1.0, 0.18, 0.3)
const BULLET_LENGTH_M: float = 0.3
## Where the ball resting against the near wall shows: this share of the half height
## below the screen's centre, above the controls bar at the bottom.
const NEAR_EDGE_SCREEN: float = 0.62

var _court: PongCourt = null
var _paddles: Array[PongPaddleView] = []
var _avatars: Array[PongAvatarView] = []
var _mine_views: Array[PongMineView] = []
var _bullet_mesh: CapsuleMesh = CapsuleMesh.new()
# What the preview draws next, one a frame.
var _later: Array[Callable] = []

@onready var camera: Camera3D = $Camera
@onready var _sun: DirectionalLight3D = $Sun
@onready var _court_view: PongCourtView = $Court
@onready var _ball: MeshInstance3D = $Ball
@onready var _shadow: MeshInstance3D = $BallShadow
@onready var _drop_line: MeshInstance3D = $DropLine
@onready var _mines: Node3D = $Mines
@onready var _bullets: Node3D = $Bullets


func _ready() -> void:
	physics_interpolation_mode = Node.PHYSICS_INTERPOLATION_MODE_OFF
	# A viewport's first camera makes itself current: nothing 3D until the first build.
	camera.clear_current(false)
	# Thinner than the bullet's hit radius: a streak, its length along the flight (the
	# capsule's axis, y, is turned onto the velocity).
	_bullet_mesh.radius = PongBullets.RADIUS_M * 0.5
	_bullet_mesh.height = BULLET_LENGTH_M
	var bullet_material: StandardMaterial3D = StandardMaterial3D.new()
	bullet_material.albedo_color = BULLET_COLOR
	bullet_material.emission_enabled = true
	bullet_material.emission = BULLET_COLOR
	_bullet_mesh.material = bullet_material


## Builds the court, the avatars and the paddles for [param court]; [param reach] is how
## far a paddle reaches from its avatar; the camera sits behind [param viewer]'s side.
func build(court: PongCourt, reach: float, beginner: bool, viewer: int = 0) -> void:
	clear()
	_court = court
	_court_view.build(court, beginner, viewer)
	var sphere: SphereMesh = _ball.mesh as SphereMesh
	sphere.radius = court.ball_radius
	sphere.height = court.ball_radius * 2.0
	for player: int in court.players:
		var avatar: PongAvatarView = PongAvatarView.new()
		avatar.name = "Avatar%d" % player
		avatar.setup(court.beginner_height, reach, PLAYER_COLORS[player], player == viewer)
		add_child(avatar)
		_avatars.append(avatar)
		var paddle: PongPaddleView = PongPaddleView.new()
		paddle.name = "Paddle%d" % player
		paddle.setup(court.paddle_radius, PLAYER_COLORS[player])
		add_child(paddle)
		_paddles.append(paddle)
	view_from(viewer)
	# Nothing 3D is drawn before the first build: its first frame compiles the sky's and
	# the meshes' shaders, for seconds, and the screen over it shows only after that.
	camera.make_current()
	# High, a little behind and to the right of the near player: shadows fall forward-left.
	_sun.look_at_from_position(
		Vector3(court.half_width, court.wall_height * 3.0, court.half_length), Vector3.ZERO
	)


## The court of [param court] with its players standing ready, behind the setup. In the
## frames after, it draws once each thing a match shows only later (a mine, a mine's
## flash, a bullet), one a frame: the first frame that draws something compiles its
## shaders, which takes seconds on a software renderer and would otherwise stall the
## match's first frame or its first mine; one a frame, a click on the setup waits for one
## of them at most. [method build] replaces it all.
func preview(court: PongCourt, reach: float, beginner: bool) -> void:
	build(court, reach, beginner)
	for player: int in court.players:
		_avatars[player].position = court.clamp_avatar(player, court.toward_back_wall(player, 0.5))
		var forward: Vector3 = PongCourt.forward(player)
		_paddles[player].place(_avatars[player].position + forward * reach * 0.5, forward)
	_ball.position = Vector3(0.0, court.ball_radius, 0.0)
	_shadow.position = Vector3(0.0, 0.004, 0.0)
	var mine_at: Vector3 = court.toward_back_wall(1, 0.5)
	_later = [
		func() -> void: add_mine(PongMines.Mine.new(1, PongMines.KINDS[0], mine_at)),
		func() -> void: explode_mine(_mine_views[0].mine),
		func() -> void:
			var bullets: PongBullets = PongBullets.new()
			bullets.fire(0, Vector3(0.0, court.ball_radius * 3.0, 0.0), Vector3.FORWARD)
			_show_bullets(bullets),
	]


func _process(_delta: float) -> void:
	if not _later.is_empty():
		var next: Callable = _later.pop_front()
		next.call()
		if _later.is_empty():
			previewed.emit()


## Puts the camera behind and above [param player]'s back wall, looking across the court
## (each local player's own side; with four players the far walls all stay in view),
## tilted so that a ball resting against the near wall shows at [constant NEAR_EDGE_SCREEN]
## (the camera's field of view is vertical).
func view_from(player: int) -> void:
	var behind: Vector3 = -PongCourt.forward(player)
	var back: float = _court.half_length + (2.5 if _court.players == 2 else 3.2)
	var height: float = _court.wall_height * (1.1 if _court.players == 2 else 1.6)
	var eye: Vector3 = behind * back + Vector3.UP * height
	var resting: Vector3 = (
		behind * (_court.half_length - _court.ball_radius) + Vector3.UP * _court.ball_radius
	)
	var below: float = atan2(eye.y - resting.y, (eye - resting).dot(behind))
	var tilt: float = below - atan(NEAR_EDGE_SCREEN * tan(deg_to_rad(camera.fov * 0.5)))
	camera.position = eye
	camera.look_at(eye - behind)
	camera.rotate_object_local(Vector3.RIGHT, -tilt)


## Draws the match as it is now.
func render(match_node: PongMatch) -> void:
	if _court == null:
		return
	var snapshot: PongState = match_node.snapshot
	var ball: Vector3 = snapshot.ball_position
	_ball.position = ball
	var height: float = maxf(ball.y - _court.ball_radius, 0.0)
	_shadow.position = Vector3(ball.x, 0.004, ball.z)
	_shadow.scale = Vector3.ONE * (1.0 + height * SHADOW_GROWTH_PER_M)
	var shadow_material: StandardMaterial3D = _shadow.get_active_material(0) as StandardMaterial3D
	shadow_material.albedo_color.a = clampf(
		1.0 - height / SHADOW_FADE_HEIGHT_M, SHADOW_MIN_ALPHA, 1.0
	)
	_drop_line.visible = height > _court.ball_radius
	_drop_line.position = Vector3(ball.x, height * 0.5, ball.z)
	_drop_line.scale = Vector3(1.0, maxf(height, 0.001), 1.0)
	for player: int in _paddles.size():
		_avatars[player].visible = not match_node.rules.is_out(player)
		_paddles[player].visible = _avatars[player].visible
		var intent: PongIntent = match_node.controllers[player].intent
		_avatars[player].position = intent.avatar
		_paddles[player].place(snapshot.paddle_centers[player], snapshot.paddle_normals[player])
		_paddles[player].show_modes(intent.spin, intent.gun, snapshot.in_contact[player])
	_show_bullets(match_node.bullets)


## Shows a newly placed mine.
func add_mine(mine: PongMines.Mine) -> void:
	var view: PongMineView = PongMineView.new()
	view.setup(mine)
	_mines.add_child(view)
	_mine_views.append(view)


## Turns a mine into its explosion.
func explode_mine(mine: PongMines.Mine) -> void:
	for view: PongMineView in _mine_views:
		if view.mine == mine:
			view.explode()
			_mine_views.erase(view)
			return


## The paddle view of [param player].
func get_paddle(player: int) -> PongPaddleView:
	return _paddles[player]


## The mine views on the court (not exploding).
func get_mine_views() -> Array[PongMineView]:
	return _mine_views


## The blob shadow under the ball.
func get_shadow() -> MeshInstance3D:
	return _shadow


func _show_bullets(bullets: PongBullets) -> void:
	while _bullets.get_child_count() < bullets.flying.size():
		var instance: MeshInstance3D = MeshInstance3D.new()
		instance.mesh = _bullet_mesh
		_bullets.add_child(instance)
	for i: int in _bullets.get_child_count():
		var instance: MeshInstance3D = _bullets.get_child(i) as MeshInstance3D
		instance.visible = i < bullets.flying.size()
		if instance.visible:
			var bullet: PongBullets.Bullet = bullets.flying[i]
			var along: Vector3 = bullet.velocity.normalized()
			if along != Vector3.ZERO:
				instance.basis = Basis(Quaternion(Vector3.UP, along))
			instance.position = bullet.position - along * BULLET_LENGTH_M * 0.5


## Empties the picture: what [method build] or [method preview] added goes (out of the
## tree at once: a build after it gives its avatars and paddles their names).
func clear() -> void:
	_court_view.clear()
	var added: Array[Node] = []
	added.append_array(_avatars)
	added.append_array(_paddles)
	added.append_array(_mines.get_children())
	added.append_array(_bullets.get_children())
	for node: Node in added:
		node.get_parent().remove_child(node)
		node.queue_free()
	_avatars.clear()
	_paddles.clear()
	_mine_views.clear()
	_later.clear()
