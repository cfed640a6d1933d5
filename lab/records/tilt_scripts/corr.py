# corr.py RUNS_CSV SETS_DIR (numpy: /usr/bin/python3): per rotation axis, the slope and correlation of the
# error against the true relative rotation (rotation vector of reference_from_input) of each run.
import csv,sys,json,math,numpy as np
rows=list(csv.DictReader(open(sys.argv[1]))); sets=sys.argv[2]
E=[];T=[]
for r in rows:
    ref=json.load(open(f"{sets}/{r['dataset']}/reference_pairs.json"))
    p=ref['pairs'][r['pair']] if 'pairs' in ref else ref[r['pair']]
    M=np.array(p['reference_from_input']).reshape(3,4); R=M[:,:3]
    # small-angle-ish: rotation vector
    ang=math.acos(max(-1,min(1,(np.trace(R)-1)/2)))
    w=np.array([R[2,1]-R[1,2],R[0,2]-R[2,0],R[1,0]-R[0,1]])/(2*math.sin(ang))*ang if ang>1e-9 else np.zeros(3)
    T.append(np.degrees(w)); E.append([float(r['error_alpha_deg']),float(r['error_beta_deg']),float(r['error_gamma_deg'])])
E=np.array(E);T=np.array(T)
for a in range(3):
    b=np.polyfit(T[:,a],E[:,a],1)[0]; c=np.corrcoef(T[:,a],E[:,a])[0,1]
    print(f"axis {a}: true rms {np.sqrt((T[:,a]**2).mean()):.2f} deg, err rms {np.sqrt((E[:,a]**2).mean()):.3f}, slope err/true {b:+.4f}, corr {c:+.2f}")
