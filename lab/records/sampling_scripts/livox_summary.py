# livox_summary.py rows.csv...: per step, how many results lie within the GICP peers' spread of the prior
# (offset_m <= peer_max_m and offset_deg <= peer_max_deg), median offsets, CONVERGENCE count, median samples/time
import csv, sys, statistics as st
for f in sys.argv[1:]:
    rows = list(csv.DictReader(open(f)))
    print(f)
    for step in ('1', '2', '3', 'all'):
        r = [x for x in rows if step == 'all' or x['step'] == step]
        peer = [x for x in r if x['peer_max_m']]
        within = [x for x in peer if float(x['offset_m']) <= float(x['peer_max_m']) and float(x['offset_deg']) <= float(x['peer_max_deg'])]
        within_deg = [x for x in peer if float(x['offset_deg']) <= float(x['peer_max_deg'])]
        conv = [x for x in r if x['termination'] == 'CONVERGENCE']
        print('  step %-3s pairs %3d conv %3d | within peers (m and deg) %3d/%d, deg only %3d | median offset %.3f m %.2f deg | p90 deg %.2f | samples med %d | finest med %s | time med %.3f s' % (
            step, len(r), len(conv), len(within), len(peer), len(within_deg), st.median(float(x['offset_m']) for x in r),
            st.median(float(x['offset_deg']) for x in r), sorted(float(x['offset_deg']) for x in r)[int(0.9 * len(r))],
            st.median(int(x['samples']) for x in r), st.median(float(x['finest_cell_m']) for x in r), st.median(float(x['time_s']) for x in r)))
