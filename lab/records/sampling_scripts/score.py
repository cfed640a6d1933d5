import csv,sys,math,collections,json,os
# score.py SETS runs.csv... : per sensor: precision of CONVERGENCE, recall on constrained pairs, RMS of right constrained runs, mean samples
sets=sys.argv[1]; free={}
for name in os.listdir(sets):
    for key,e in json.load(open(os.path.join(sets,name,'reference_pairs.json'))).items(): free[(name,key)]=bool(e.get('free_directions'))
for f in sys.argv[2:]:
    rows=list(csv.DictReader(open(f)))
    by=collections.defaultdict(list)
    for r in rows: by[r['dataset'].split('_')[0]].append(r)
    by['ALL']=rows
    print(f)
    for k,v in sorted(by.items()):
        conv=[r for r in v if r['termination']=='CONVERGENCE']; cr=[r for r in conv if r['right']=='1']
        fixed=[r for r in v if not free[(r['dataset'],r['pair'])]]
        fr=[r for r in fixed if r['right']=='1']; frc=[r for r in fr if r['termination']=='CONVERGENCE']
        rmsr=math.sqrt(sum(float(r['rotation_error_deg'])**2 for r in fr)/max(1,len(fr)))
        rmst=math.sqrt(sum(float(r['translation_error_m'])**2 for r in fr)/max(1,len(fr)))
        smp=sum(float(r['fit_points']) for r in v)/len(v)
        t=sorted(float(r['total_ms']) for r in v)[len(v)//2]
        print('  %-6s conv %3d wrong %2d P %.3f | constrained right %3d/%3d R %.3f rms %.2fcm %.3fdeg | samples %.0f t_med %.3f' % (k,len(conv),len(conv)-len(cr),len(cr)/max(1,len(conv)),len(fr),len(fixed),len(frc)/max(1,len(fr)),rmst*100,rmsr,smp,t))
