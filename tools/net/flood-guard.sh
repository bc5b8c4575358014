#!/usr/bin/env bash
# The kernel's guard of a Haptic Battle Pong server against floods of ENet connection requests
# (docs/pong-networking.md, "Floods"): an nftables table that lets each source address send
# at most 4 connection requests a second (a burst of 8), and all sources together 100, and
# drops the rest before ENet gives them a slot. Game traffic of connected players is never
# touched: a connection request is the one datagram addressed to no peer yet (peer id 0xFFF
# in ENet's 4-byte header), so the rule reads those 12 bits and nothing else.
#
#   tools/net/flood-guard.sh [PORT]            install (or replace) the guard for PORT (7420)
#   tools/net/flood-guard.sh --remove          remove it
#   tools/net/flood-guard.sh --print [PORT]    print the ruleset instead
#
# Needs root and nftables (Debian: apt-get install nftables); it lasts until reboot (add the
# printed ruleset to /etc/nftables.conf to keep it). Why these numbers: ENet keeps a slot for
# every connection request it answers for about 31.5 s; a server has 4095 slots
# (PongNetProtocol.ENET_SLOTS), so 100 requests a second from everywhere hold at most about
# 3,200 of them and players always find one, and one address at 4 a second holds about 130.
set -euo pipefail

table=pong_flood_guard
per_source=4
burst=8
all_sources=100

ruleset() {
  local port=$1
  cat <<EOF
table inet $table {
	set sources4 {
		type ipv4_addr
		size 65536
		flags dynamic,timeout
		timeout 60s
	}
	set sources6 {
		type ipv6_addr
		size 65536
		flags dynamic,timeout
		timeout 60s
	}
	chain input {
		type filter hook input priority filter; policy accept;
		udp dport $port @th,64,16 & 0x0fff == 0x0fff jump connection_request
	}
	chain connection_request {
		update @sources4 { ip saddr limit rate over $per_source/second burst $burst packets } counter drop
		update @sources6 { ip6 saddr & ffff:ffff:ffff:ffff:: limit rate over $per_source/second burst $burst packets } counter drop
		limit rate over $all_sources/second burst $all_sources packets counter drop
	}
}
EOF
}

case "${1:-}" in
  --remove)
    nft delete table inet "$table" 2>/dev/null || true
    ;;
  --print)
    ruleset "${2:-7420}"
    ;;
  *)
    port=${1:-7420}
    [[ $port =~ ^[0-9]+$ ]] && ((port > 0 && port < 65536)) || {
      echo "flood-guard.sh: not a port: $port" >&2
      exit 2
    }
    nft delete table inet "$table" 2>/dev/null || true
    ruleset "$port" | nft -f -
    ;;
esac
