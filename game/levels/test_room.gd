class_name TestRoom
extends Level
## A closed room with a slanted block: the smallest real level, used by the foundation
## tests and by [code]make play[/code] until the full level exists.
##
## Everything it offers comes from [Level]: [signal Level.player_bumped] relays the
## player's bumps; the autopilot path is the spawn point alone (the room has no goal).
