# tilt_stats.py RUNS_CSV: runs, right, CONVERGENCE, wrong CONVERGENCE and the tilt error (hypot of
# error_alpha_deg, error_beta_deg) of an mlndt_suite runs.csv.
import csv,sys,math
rows=list(csv.DictReader(open(sys.argv[1])))
def f(r,k):
    try: return float(r[k])
    except: return float('nan')
n=len(rows)
tilt=[math.hypot(f(r,'error_alpha_deg'),f(r,'error_beta_deg')) for r in rows]
tr=[f(r,'translation_error_m')*100 for r in rows]
rot=[f(r,'rotation_error_deg') for r in rows]
conv=[r['termination']=='CONVERGENCE' for r in rows]
right=[r['right']=='1' or r['right'].lower()=='true' for r in rows]
wc=sum(1 for c,rt in zip(conv,right) if c and not rt)
rms=lambda v: math.sqrt(sum(x*x for x in v)/len(v)) if v else float('nan')
over1=sum(1 for t in tilt if t>1.0); over05=sum(1 for t in tilt if t>0.5)
print(f"runs {n} right {sum(right)} CONV {sum(conv)} wrongCONV {wc} | tilt RMS {rms(tilt):.3f} deg, >0.5: {over05}, >1: {over1}, max {max(tilt):.2f} | rot RMS {rms(rot):.3f} | trans RMS {rms(tr):.2f} cm | mean ms {sum(f(r,'registration_ms') for r in rows)/n:.0f}")
