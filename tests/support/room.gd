class_name TestRoom
extends Level
## A closed room with a slanted block: the smallest real level, for the tests that steer a
## player into walls (the game itself plays level 1 and has no test level).
##
## Everything it offers comes from [Level]: [signal Level.player_bumped] relays the
## player's bumps; the autopilot path is the spawn point alone (the room has no goal).
