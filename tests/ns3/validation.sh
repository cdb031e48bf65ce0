#!/usr/bin/env bash
# The ns3_wifi channel against ns-3 alone: robots held still on an open 20 m x 16 m floor,
# each broadcasting its 56-byte state every PERIOD with a random phase on 802.11b at 1 Mbit/s,
# run by covsim (its kernel, the co-simulated peer) and by tests/ns3/broadcast_reference.cc
# (the same radios and schedule in one plain ns-3 program). At three offered loads (periods
# 0.5, 0.05 and 0.01 s for 20 robots: about 3%, 30% and saturating airtime) the delivery
# ratios must agree within 0.05 and the mean latencies within 25% (or 0.2 ms): the phases
# are drawn by different generators, so the two agree in distribution, not bit for bit.
#   validation.sh COVSIM REFERENCE WORK_DIR
set -euo pipefail
covsim=$1 reference=$2 work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
positions=""
: > positions.txt
for i in $(seq 0 19); do
  x=$(( 2 + 4 * (i % 5) )) y=$(( 2 + 4 * (i / 5) ))
  echo "$x $y" >> positions.txt
  positions+="${positions:+, }[$x, $y]"
done
duration=20
fail=0
for period in 0.5 0.05 0.01; do
  cat > still.json <<JSON
{"environment": {"outer": [[0, 0], [20, 0], [20, 16], [0, 16]]},
 "density": {"type": "uniform"},
 "robots": {"positions": [$positions]},
 "controller": {"type": "external"},
 "network": {"channel": {"type": "ns3_wifi", "standard": "b", "rate": "DsssRate1Mbps"},
             "broadcast_period": $period},
 "convergence": {"max_time": $duration},
 "seed": 3}
JSON
  "$covsim" run still.json --out "run-$period" >/dev/null
  read -r ours_ratio ours_latency < <(/usr/bin/python3 -c "
import json; n = json.load(open('run-$period/final.json'))['network']
print(n['delivery_ratio'], n['latency_mean'])")
  read -r ref_ratio ref_latency < <("$reference" positions.txt "$period" "$duration" 56 3 |
                                     awk '{v[$1] = $2} END {print v["delivery_ratio"], v["latency_mean"]}')
  verdict=$(/usr/bin/python3 -c "
a, b, la, lb = $ours_ratio, $ref_ratio, $ours_latency, $ref_latency
ok = abs(a - b) <= 0.05 and abs(la - lb) <= max(0.25 * lb, 2e-4)
print('ok' if ok else 'DIFFER')")
  printf 'period %-5s delivery covsim %.4f ns-3 %.4f   latency covsim %.6f s ns-3 %.6f s   %s\n' \
    "$period" "$ours_ratio" "$ref_ratio" "$ours_latency" "$ref_latency" "$verdict"
  [ "$verdict" = ok ] || fail=1
done
exit $fail
