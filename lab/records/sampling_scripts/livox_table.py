# livox_table.py ALIGN OUTDIR [flags...]: every pair of fastlio_avia_hku_2_pairs from the identity with
# mlndt_align; writes OUTDIR/rows.csv: pair, termination, samples, finest cell, offset from prior (m, deg),
# the GICP peers' offsets from the prior (min..max over the five peers), time.
import json, subprocess, sys, os, math, csv
import numpy as np
align, out = sys.argv[1], sys.argv[2]; flags = sys.argv[3:]
D = '/work/shared/data/fastlio_avia_hku_2_pairs'
pairs = json.load(open(D + '/reference_pairs.json'))
os.makedirs(out, exist_ok=True)
def mat(v):
    m = np.eye(4); m[:3, :4] = np.array(v).reshape(3, 4); return m
rows = []
for key, e in pairs.items():
    i, j = key.split('_')
    js = '%s/%s.json' % (out, key)
    subprocess.run([align, '%s/pcd/%06d.pcd' % (D, int(i)), '%s/pcd/%06d.pcd' % (D, int(j)), '--output_json=' + js] + flags,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    r = json.load(open(js))['registration']
    T = np.array(r['reference_from_input']); P = mat(e['prior_from_input'])
    d = np.linalg.inv(P) @ T
    dt = np.linalg.norm(d[:3, 3]); dr = math.degrees(math.acos(max(-1, min(1, (np.trace(d[:3, :3]) - 1) / 2))))
    peers = e.get('peer_offsets_from_prior_m_deg', {})
    pm = [v[0] for v in peers.values()]; pd = [v[1] for v in peers.values()]
    rows.append([key, int(j) - int(i), r['termination_type'], r['sampled_points'], '%.2f' % r['finest_cell_size_m'],
                 '%.4f' % dt, '%.3f' % dr, '%.4f' % max(pm) if pm else '', '%.3f' % max(pd) if pd else '',
                 '%.4f' % min(pm) if pm else '', '%.3f' % min(pd) if pd else '', '%.4f' % r['total_time_s']])
with open(out + '/rows.csv', 'w') as f:
    w = csv.writer(f); w.writerow(['pair', 'step', 'termination', 'samples', 'finest_cell_m', 'offset_m', 'offset_deg',
                                   'peer_max_m', 'peer_max_deg', 'peer_min_m', 'peer_min_deg', 'time_s']); w.writerows(rows)
print('wrote', out + '/rows.csv', len(rows))
