extends TestSuite
## Who is the ball's master, without sockets: transfers only from the server, applied in
## epoch order, hand-off requests honoured only from the current master at the current
## epoch, stream states only from the current epoch's master and in order.

const HOST: int = 1
const CLIENT: int = 42


func _pair() -> Array[PongNetAuthority]:
	var owners: PackedInt64Array = PackedInt64Array([HOST, CLIENT])
	return [PongNetAuthority.new(HOST, owners.duplicate()), PongNetAuthority.new(CLIENT, owners)]


func _apply_everywhere(peers: Array[PongNetAuthority], transfer: Dictionary) -> void:
	for peer: PongNetAuthority in peers:
		assert_eq(peer.apply_transfer(HOST, transfer), "", "a server transfer is applied")


func test_the_owner_of_the_served_territory_is_master_everywhere() -> void:
	var peers: Array[PongNetAuthority] = _pair()
	var serve: Dictionary = peers[0].next_transfer(PongNetFacts.TransferKind.SERVE, 1)
	assert_eq(serve["master"], CLIENT)
	_apply_everywhere(peers, serve)
	assert_false(peers[0].is_master())
	assert_true(peers[1].is_master())
	assert_eq([peers[0].epoch, peers[1].epoch], [1, 1])


func test_a_hand_off_leaves_no_master_until_the_transfer_arrives_never_two() -> void:
	var peers: Array[PongNetAuthority] = _pair()
	_apply_everywhere(peers, peers[0].next_transfer(PongNetFacts.TransferKind.SERVE, 0))
	assert_true(peers[0].is_master())
	var request: Dictionary = peers[0].relinquish(1)
	assert_eq(request, {"epoch": 1, "territory": 1})
	assert_false(peers[0].is_master(), "the old master stops at the crossing")
	assert_false(peers[1].is_master(), "the new one waits for the transfer")
	var seen: int = request["epoch"]
	var territory: int = request["territory"]
	assert_eq(peers[0].check_request(HOST, seen, territory), "")
	_apply_everywhere(peers, peers[0].next_transfer(PongNetFacts.TransferKind.HANDOFF, 1))
	assert_eq([peers[0].is_master(), peers[1].is_master()], [false, true])
	assert_eq(peers[0].relinquish(0), {}, "a follower has nothing to hand off")


func test_a_request_raced_by_a_newer_transfer_is_refused_and_both_end_the_same() -> void:
	var peers: Array[PongNetAuthority] = _pair()
	_apply_everywhere(peers, peers[0].next_transfer(PongNetFacts.TransferKind.SERVE, 1))
	# The client crosses into territory 0 and asks; meanwhile the server serves again.
	var request: Dictionary = peers[1].relinquish(0)
	_apply_everywhere(peers, peers[0].next_transfer(PongNetFacts.TransferKind.SERVE, 1))
	var seen: int = request["epoch"]
	var territory: int = request["territory"]
	var reason: String = peers[0].check_request(CLIENT, seen, territory)
	assert_true(reason.begins_with("stale hand-off request"), reason)
	assert_true(peers[1].is_master(), "the newer serve made the client master again")
	assert_false(peers[0].is_master())
	assert_eq(peers[0].history, peers[1].history, "the same transfers in the same order")


func test_only_the_master_may_ask_and_only_the_server_may_transfer() -> void:
	var peers: Array[PongNetAuthority] = _pair()
	_apply_everywhere(peers, peers[0].next_transfer(PongNetFacts.TransferKind.SERVE, 0))
	var reason: String = peers[0].check_request(CLIENT, 1, 1)
	assert_true(reason.contains("not the master"), reason)
	reason = peers[0].check_request(HOST, 1, 7)
	assert_true(reason.contains("territory 7"), reason)
	var forged: Dictionary = {"epoch": 9, "kind": 1, "territory": 1, "master": CLIENT}
	reason = peers[0].apply_transfer(CLIENT, forged)
	assert_true(reason.contains("only the server"), reason)
	assert_eq(peers[0].epoch, 1, "a refused transfer changes nothing")
	assert_eq(peers[0].apply_transfer(HOST, {"epoch": 1, "master": CLIENT}).is_empty(), false)
	assert_eq(peers[0].master_peer, HOST, "a stale transfer changes nothing")
	assert_eq(
		peers[0].refusals.values().reduce(func(a: int, b: int) -> int: return a + b, 0),
		4,
		"each refusal counted"
	)


func test_stream_states_only_from_the_master_of_this_epoch_in_order() -> void:
	var peers: Array[PongNetAuthority] = _pair()
	var follower: PongNetAuthority = peers[1]
	_apply_everywhere(peers, peers[0].next_transfer(PongNetFacts.TransferKind.SERVE, 0))
	assert_eq(follower.accept_state(HOST, 1, 5), "")
	assert_ne(follower.accept_state(HOST, 1, 5), "", "a repeat is dropped")
	assert_ne(follower.accept_state(HOST, 1, 4), "", "a late one is dropped")
	assert_eq(follower.accept_state(HOST, 1, 9), "")
	assert_ne(follower.accept_state(HOST, 0, 10), "", "an old epoch is dropped")
	assert_ne(follower.accept_state(HOST, 2, 10), "", "a future epoch waits for its transfer")
	assert_ne(follower.accept_state(CLIENT, 1, 11), "", "not from a non-master")
	_apply_everywhere(peers, peers[0].next_transfer(PongNetFacts.TransferKind.HANDOFF, 1))
	assert_eq(peers[0].accept_state(CLIENT, 2, 1), "", "seq starts over with the epoch")


func test_a_peer_that_leaves_gives_its_seats_to_the_server() -> void:
	var peers: Array[PongNetAuthority] = _pair()
	_apply_everywhere(peers, peers[0].next_transfer(PongNetFacts.TransferKind.SERVE, 1))
	assert_eq(peers[0].release_peer(CLIENT), PackedInt32Array([1]))
	assert_eq(peers[0].owner_of(1), HOST)
	var takeover: Dictionary = peers[0].next_transfer(PongNetFacts.TransferKind.TAKEOVER, 1)
	assert_eq(takeover["master"], HOST)
	assert_eq(peers[0].apply_transfer(HOST, takeover), "")
	assert_true(peers[0].is_master())
	assert_eq(peers[0].master_at(1), CLIENT)
	assert_eq(peers[0].master_at(2), HOST)
	assert_eq(peers[0].master_at(5), 0)
