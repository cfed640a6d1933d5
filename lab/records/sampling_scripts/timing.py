# timing.py: one-shot total_time_s of mlndt_align, alternating builds, 5 rounds; medians
import json, subprocess, statistics as st, sys
K = '/work/shared/data/kitti00_frames_0000_0007/pcd/'; L = '/work/shared/data/fastlio_avia_hku_2_pairs/pcd/'
pairs = {'kitti 0->1': (K + '000000.pcd', K + '000001.pcd'), 'livox 202->203': (L + '000202.pcd', L + '000203.pcd')}
cfgs = {'today (main)': ['/work/main/build/tools/mlndt_align'], 'branch default': ['/work/wt/sampling/build/tools/mlndt_align'],
        'branch --gbs_min_samples=8000': ['/work/wt/sampling/build/tools/mlndt_align', '--gbs_min_samples=8000']}
t = {(p, c): [] for p in pairs for c in cfgs}; s = {}
for rnd in range(5):
    for p, (a, b) in pairs.items():
        for c, cmd in cfgs.items():
            subprocess.run([cmd[0], a, b, '--output_json=/tmp/sampling/t.json'] + cmd[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            r = json.load(open('/tmp/sampling/t.json'))['registration']; t[(p, c)].append(r['total_time_s']); s[(p, c)] = r['sampled_points']
for (p, c), v in t.items(): print('%-15s %-30s samples %6d  median %.3f s  (runs %s)' % (p, c, s[(p, c)], st.median(v), ' '.join('%.3f' % x for x in v)))
