class_name PongSetup
extends CanvasLayer
## The first thing the Pong screen shows: the options first (how hard the computer plays,
## beginner mode, the court: two players, or four on a square court, the computer taking
## the sides nobody plays), then who plays (against the computer, two players on one
## machine, computer against computer), or, without the extension's Pong renderer, why
## there is no game. It only emits signals.

## Start a match in [param mode] (a [enum PongMatch.Mode]).
signal start_requested(mode: PongMatch.Mode, beginner: bool)
signal back_requested
## Open the network game's lobby.
signal network_requested
## The court chosen changed: [param players] (2 or 4), in beginner mode or not.
signal court_changed(players: int, beginner: bool)

## Beginner mode starts ticked: the paper's starting point for novices, and the mode in
## which a first-time player rallies against the Easy computer (tests/pong/
## test_pong_newcomer.gd; with gravity the same scripted player touches the ball but cannot
## keep it in play).
const BEGINNER_FIRST: bool = true
## Said in place of the buttons while the court behind them is drawn the first time.
const PREPARING_TEXT: String = "Preparing the court..."

@onready var vs_computer_button: Button = %VsComputerButton
@onready var two_players_button: Button = %TwoPlayersButton
@onready var demo_button: Button = %DemoButton
@onready var network_button: Button = %NetworkButton
@onready var beginner_check: CheckBox = %BeginnerCheck
@onready var four_players_check: CheckBox = %FourPlayersCheck
@onready var difficulty_option: OptionButton = %DifficultyOption
@onready var back_button: Button = %BackButton
@onready var _buttons: Control = %Buttons
@onready var _subtitle: Label = %Subtitle
@onready var _rules: String = _subtitle.text


func _ready() -> void:
	vs_computer_button.pressed.connect(_start.bind(PongMatch.Mode.VS_COMPUTER))
	two_players_button.pressed.connect(_start.bind(PongMatch.Mode.TWO_PLAYERS))
	demo_button.pressed.connect(_start.bind(PongMatch.Mode.DEMO))
	network_button.pressed.connect(network_requested.emit)
	back_button.pressed.connect(back_requested.emit)
	for level: int in PongAiLevel.NAMES.size():
		difficulty_option.add_item(PongAiLevel.NAMES[level], level)
	difficulty_option.select(PongAiLevel.Level.EASY)
	beginner_check.button_pressed = BEGINNER_FIRST
	for check: CheckBox in [beginner_check, four_players_check]:
		check.toggled.connect(
			func(_on: bool) -> void:
				court_changed.emit(get_players(), beginner_check.button_pressed)
		)
	UiFocus.grab_later(vs_computer_button)


func _unhandled_input(event: InputEvent) -> void:
	if visible and event.is_action_pressed(&"ui_cancel"):
		get_viewport().set_input_as_handled()
		back_requested.emit()


## No game: says why, and offers only the way back.
func show_offline(reason: String) -> void:
	_subtitle.text = reason
	_buttons.visible = false
	UiFocus.grab_later(back_button)


## While [param on], the setup says it is preparing the court and offers no button but
## the way back: a click then would wait behind the court's first frame.
func set_preparing(on: bool) -> void:
	_subtitle.text = PREPARING_TEXT if on else _rules
	_buttons.visible = not on
	UiFocus.grab_later(back_button if on else vs_computer_button)


## Whether the setup still says it is preparing the court.
func is_preparing() -> bool:
	return not _buttons.visible and _subtitle.text == PREPARING_TEXT


## How many players the court is set for: 2, or 4 when [member four_players_check] is on.
func get_players() -> int:
	return 4 if four_players_check.button_pressed else 2


## How hard the computer plays, as chosen.
func get_difficulty() -> PongAiLevel.Level:
	var level: int = difficulty_option.get_selected_id()
	return level as PongAiLevel.Level


## The text under the heading.
func get_message() -> String:
	return _subtitle.text


func _start(mode: PongMatch.Mode) -> void:
	start_requested.emit(mode, beginner_check.button_pressed)
