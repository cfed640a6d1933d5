#!/usr/bin/env python3
"""Verdict and right/wrong changes between two sim_suite.sh runs (lab/records/prior_hold.md):
prior_diff.py BASE_DIR NEW_DIR counts, per start kind, the runs whose termination or "right" changed
(R = right, w = wrong), keyed by (start kind, before, after)."""
import csv, sys, collections
a={(r['dataset'],r['pair'],r['start_kind'],r['start']):r for r in csv.DictReader(open(sys.argv[1]+'/suite/runs.csv'))}
b={(r['dataset'],r['pair'],r['start_kind'],r['start']):r for r in csv.DictReader(open(sys.argv[2]+'/suite/runs.csv'))}
c=collections.Counter()
for k in a:
    if k not in b: continue
    ra,rb=a[k],b[k]
    if ra['right']!=rb['right'] or ra['termination']!=rb['termination']:
        c[(k[2],ra['termination'][:4]+('R' if ra['right']=='1' else 'w'),rb['termination'][:4]+('R' if rb['right']=='1' else 'w'))]+=1
for k,v in sorted(c.items()): print(k,v)
