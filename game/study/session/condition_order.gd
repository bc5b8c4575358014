class_name ConditionOrder
extends RefCounted
## The order in which a participant meets the three conditions.
##
## [b]random[/b]: a Fisher–Yates shuffle of [member StudyFormat.conditions] driven by a
## [RandomNumberGenerator] seeded with the participant's recorded seed, so the order can be
## recomputed from participant.json. [b]latin_square[/b]: the six orders of a Williams
## design for three conditions (every condition in every position, and every condition
## following every other equally often), assigned in turn: the n-th participant of the
## study folder (counting from 0) gets row n mod 6.

## The Williams design for three conditions (rows), as indices into
## [member StudyFormat.conditions].
const LATIN_SQUARE: Array = [
	[0, 1, 2],
	[1, 2, 0],
	[2, 0, 1],
	[2, 1, 0],
	[0, 2, 1],
	[1, 0, 2],
]


## The order drawn from [param order_seed].
static func random_order(order_seed: int) -> PackedStringArray:
	var rng: RandomNumberGenerator = RandomNumberGenerator.new()
	rng.seed = order_seed
	var order: PackedStringArray = StudyFormat.conditions.duplicate()
	for i: int in range(order.size() - 1, 0, -1):
		var j: int = rng.randi_range(0, i)
		var swap: String = order[i]
		order[i] = order[j]
		order[j] = swap
	return order


## Row [code]participant_number mod 6[/code] of [constant LATIN_SQUARE].
static func latin_square_order(participant_number: int) -> PackedStringArray:
	var row: Array = LATIN_SQUARE[posmod(participant_number, LATIN_SQUARE.size())]
	var order: PackedStringArray = PackedStringArray()
	for index: Variant in row:
		var position: int = index
		order.append(StudyFormat.conditions[position])
	return order


## A fresh seed (non-negative, fits 31 bits) for a new participant.
static func new_seed() -> int:
	var rng: RandomNumberGenerator = RandomNumberGenerator.new()
	rng.randomize()
	return rng.randi() & 0x7FFFFFFF
