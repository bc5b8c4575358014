#pragma once

// What the Pong servo hands the game (servo -> game), defined in pong_state.schema.toml:
//   PongState  a snapshot after every tick, through a seqlock;
//   PongEvent  bounces, paddle contacts and territory changes, through an SPSC queue the
//              game drains every frame (a full queue drops the event and counts it).
// World space, except the hand forces (the device player's device space, N).

#include "renderers/pong/ball.h"
#include "renderers/pong/court.h"
#include "renderers/pong/pong_input.h"
#include "renderers/pong/pong_state.gen.h"
