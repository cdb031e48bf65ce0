#!/usr/bin/env bash
# The ns3_wifi channel through the covsim program: a run of the U room converges with its
# radio measures, repeats bit for bit, replays, and gives the same runs at --jobs 1 and 2;
# keys the radio decides itself and a rate the standard lacks are exit 2; a peer that cannot
# start, dies or answers garbage is exit 1 naming it; SIGTERM ends a run waiting on a peer.
#   channel_cli.sh COVSIM SOURCE_DIR WORK_DIR
set -euo pipefail
covsim=$1 src=$2 work=$3
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$work"; mkdir -p "$work"; cd "$work"
radio='network.channel={"type": "ns3_wifi", "standard": "g"}'
json() { /usr/bin/python3 -c "import json, sys; print(eval('json.load(open(sys.argv[1]))' + sys.argv[2]))" "$@"; }

"$covsim" run "$src/scenarios/u_shape.json" --set "$radio" --out a --trace a.trace >/dev/null
"$covsim" run "$src/scenarios/u_shape.json" --set "$radio" --out b >/dev/null
[ "$(json a/final.json "['converged']")" = True ] || fail "the U room did not converge"
[ "$(json a/final.json "['fingerprint']")" = "$(json b/final.json "['fingerprint']")" ] ||
  fail "two runs differ"
ratio=$(json a/final.json "['network']['delivery_ratio']")
occupancy=$(json a/final.json "['network']['channel_occupancy']")
/usr/bin/python3 -c "assert 0.9 <= $ratio <= 1 and 0 < $occupancy < 1" ||
  fail "radio measures out of range: delivery $ratio, occupancy $occupancy"
for key in phy_drops transmissions mac_drops latency_mean latency_p95; do
  [ "$(json a/final.json "['network']['$key']")" != None ] || fail "network.$key is null"
done
"$covsim" replay a.trace | grep -q "replay matches" || fail "the trace does not replay"
# Broadcasts at the motion steps' instants (no random phase): announced to the radio with the
# step, made after its moves; on 802.11 they all go at once and collide.
"$covsim" run "$src/scenarios/u_shape.json" --set "$radio" --set network.random_phase=false \
  --out sync >/dev/null || fail "synchronised broadcasts: the run failed"
/usr/bin/python3 -c "assert $(json sync/final.json "['network']['delivery_ratio']") < 0.1" ||
  fail "synchronised broadcasts did not collide: $(json sync/final.json "['network']")"

# Robots that map the room share their maps over the radio: every broadcast reserves the map's
# bytes (its size is announced before its content), the maps merge, the run converges; a map
# payload past 802.11's largest MSDU is exit 2 naming mapping.max_bytes.
"$covsim" run "$src/scenarios/two_obstacles.json" --set "$radio" --set environment.known=none \
  --set sensor.range=0.5 --set mapping.compare_known=false --out mapped >/dev/null ||
  fail "the mapping run failed"
[ "$(json mapped/final.json "['converged']")" = True ] || fail "the mapping run did not converge"
/usr/bin/python3 -c "assert $(json mapped/final.json "['mapping']['bytes']") > 0" ||
  fail "no map bytes went over the radio"
[ "$(json mapped/final.json "['mapping']['obstacles_known_min']")" = 2 ] ||
  fail "a robot did not learn both obstacles: $(json mapped/final.json "['mapping']")"
"$covsim" run "$src/scenarios/two_obstacles.json" --set "$radio" --out unmapped >/dev/null
/usr/bin/python3 -c "assert $(json mapped/final.json "['network']['channel_occupancy']") > \
  1.5 * $(json unmapped/final.json "['network']['channel_occupancy']")" ||
  fail "map payloads did not lengthen the frames"
# The full stack: Ω unknown, 5 mm tracking, 1 cm range noise (an occupancy grid shared as
# patches over the radio), bodies with ORCA on a differential drive, grid A* on the sensed map.
for scenario in two_obstacles u_shape; do
  "$covsim" run "$src/scenarios/$scenario.json" --set "$radio" --set environment.known=none \
    --set robots.localization='{"type": "tracking", "noise": 0.005}' \
    --set sensor.noise.sigma=0.01 --set sensor.range=0.5 --set robots.radius=0.02 \
    --set robots.avoidance.type=orca --set robots.kinematics.type=differential_drive \
    --set planner.type=grid_astar --set mapping.compare_known=false --out "full_$scenario" \
    >/dev/null || fail "the full stack on $scenario failed"
  f=full_$scenario/final.json
  [ "$(json $f "['converged']")" = True ] || fail "the full stack on $scenario did not converge"
  [ "$(json $f "['bodies']['contact_time']")" = 0.0 ] &&
    [ "$(json $f "['bodies']['wall_contacts']")" = 0 ] ||
    fail "the full stack on $scenario touched: $(json $f "['bodies']")"
  [ "$(json $f "['mapping']['model']")" = occupancy ] || fail "no occupancy grid on $scenario"
  /usr/bin/python3 -c "assert $(json $f "['mapping']['bytes']") > 0" ||
    fail "no map patches went over the radio on $scenario"
done

set +e
"$covsim" run "$src/scenarios/two_obstacles.json" --set "$radio" --set environment.known=none \
  --set mapping.max_bytes=4000 --out too_big >/dev/null 2>err.txt
code=$?
set -e
[ $code = 2 ] && grep -q "mapping.max_bytes" err.txt || fail "a too large map payload: exit $code"

# A sweep's runs, each with its own peer, are the same at any parallelism.
cat > sweep.json <<JSON
{"scenario": "$src/scenarios/u_shape.json",
 "grid": {"network.channel.type": ["ns3_wifi"], "network.broadcast_period": [0.02, 0.2]},
 "seeds": [1, 2]}
JSON
"$covsim" sweep sweep.json --out s1 --jobs 1 >/dev/null 2>&1
"$covsim" sweep sweep.json --out s2 --jobs 2 >/dev/null 2>&1
fingerprints() { /usr/bin/python3 -c "
import csv, sys; print([r['fingerprint'] for r in csv.DictReader(open(sys.argv[1]))])" "$1"; }
[ "$(fingerprints s1/runs.csv)" = "$(fingerprints s2/runs.csv)" ] || fail "--jobs changes runs"

# Walls: robots held still, A and C in one room, B beyond a wall (or on its far face, as a
# robot settled at a projection is). A loss of 200 dB per wall leaves A <-> C alone: 2 of 6
# links; no loss, all 6.
for b in "[8, 2]" "[5.1, 2]"; do
  for wall_loss in 0 200; do
    cat > wall.json <<JSON
{"environment": {"outer": [[0, 0], [10, 0], [10, 4], [0, 4]],
                 "holes": [[[4.9, 0.5], [5.1, 0.5], [5.1, 3.5], [4.9, 3.5]]]},
 "density": {"type": "uniform"}, "robots": {"positions": [[2, 2], [3, 2], $b]},
 "controller": {"type": "external"}, "convergence": {"max_time": 5}, "seed": 1,
 "network": {"channel": {"type": "ns3_wifi", "standard": "g", "wall_loss": $wall_loss}}}
JSON
    "$covsim" run wall.json --out wall >/dev/null
    want=$([ "$wall_loss" = 0 ] && echo 1.0 || echo 0.3333333333333333)
    [ "$(json wall/final.json "['network']['delivery_ratio']")" = "$want" ] ||
      fail "B at $b, $wall_loss dB per wall: delivery $(json wall/final.json "['network']")"
    # The communication graph is who hears whom: B cut off behind the wall is a component.
    components=$(/usr/bin/python3 -c "
import csv; print(list(csv.DictReader(open('wall/metrics.csv')))[-1]['components'])")
    [ "$components" = "$([ "$wall_loss" = 0 ] && echo 1 || echo 2)" ] ||
      fail "B at $b, $wall_loss dB per wall: $components components"
  done
done

# Keys the radio decides, and a mode the standard lacks: bad input; the abstract channel's
# defaults stated beside it are not.
"$covsim" run "$src/scenarios/u_shape.json" --set "$radio" --set network.line_of_sight=false \
  --out los >/dev/null || fail "line_of_sight=false beside ns3_wifi refused"
set +e
"$covsim" run "$src/scenarios/u_shape.json" --set "$radio" --set network.range=2 --out r \
  >/dev/null 2>err.txt
rc=$?
set -e
[ $rc -eq 2 ] && grep -q 'network.range: does not apply to the ns3_wifi channel' err.txt ||
  fail "network.range with ns3_wifi: exit $rc: $(cat err.txt)"
set +e
"$covsim" run "$src/scenarios/u_shape.json" \
  --set 'network.channel={"type": "ns3_wifi", "standard": "b", "rate": "OfdmRate6Mbps"}' \
  --out r >/dev/null 2>err.txt
rc=$?
set -e
[ $rc -eq 2 ] && grep -q '802.11b has no mode "OfdmRate6Mbps"' err.txt ||
  fail "a rate 802.11b lacks: exit $rc: $(cat err.txt)"

# Peers that fail: exit 1 with the peer named and why, and no run folder.
check_peer() {  # PEER EXPECTED_TEXT
  set +e
  COVSIM_NS3_PEER=$1 timeout 60 "$covsim" run "$src/scenarios/u_shape.json" --set "$radio" \
    --out bad >/dev/null 2>err.txt
  rc=$?
  set -e
  [ $rc -eq 1 ] && grep -q -- "$2" err.txt && [ ! -e bad ] ||
    fail "peer $1: expected exit 1 with '$2', got $rc: $(cat err.txt)"
}
check_peer "$work/no-such-peer" "cannot start"
check_peer /bin/false "exited with status 1"
check_peer /usr/bin/yes "more than the protocol allows"
printf '#!/bin/sh\nkill -SEGV $$\n' > crash.sh && chmod +x crash.sh
check_peer "$work/crash.sh" "killed by signal 11"

# A peer that never answers: SIGTERM still ends the run, at once.
printf '#!/bin/sh\nexec sleep 600\n' > mute.sh && chmod +x mute.sh
set +e
COVSIM_NS3_PEER=$work/mute.sh "$covsim" run "$src/scenarios/u_shape.json" --set "$radio" \
  --out mute >/dev/null 2>err.txt &
pid=$!
sleep 2
kill -TERM $pid
start=$SECONDS
wait $pid
rc=$?
set -e
[ $rc -eq 143 ] && [ $((SECONDS - start)) -le 10 ] && [ ! -e mute ] ||
  fail "SIGTERM while the peer is silent: exit $rc after $((SECONDS - start)) s: $(cat err.txt)"
echo "ok"
