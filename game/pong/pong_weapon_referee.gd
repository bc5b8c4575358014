class_name PongWeaponReferee
extends RefCounted
## Who decides what the bullets and mines did, and where a hurt they cause goes: the seam
## between [PongMatch]'s weapons and a networked match. This base is the local game's: the
## match judges every seat and a hurt costs health at once. A networked match replaces it
## ([PongNetWeapons]): a peer judges only the seats it drives (it has their exact avatars),
## and a hurt it judges reaches every peer, which all apply it the same way.


## Whether this match decides the hits on [param seat] (bullets crossing its avatar, its
## avatar stepping on a mine). Hits on other seats are left to whoever does.
func judges(_seat: int) -> bool:
	return true


## [param victim] was hurt by [param cause] ([constant PongRules.CAUSE_BULLET] or
## [constant PongRules.CAUSE_MINE]): [param weapon_owner]'s bullet or mine number
## [param weapon_id]; [param rules] are the match's. Called after the victim's own effect
## (the hit, the mine) has started.
func hurt(
	rules: PongRules, victim: int, cause: StringName, _weapon_owner: int, _weapon_id: int
) -> void:
	rules.hurt(victim, cause)
