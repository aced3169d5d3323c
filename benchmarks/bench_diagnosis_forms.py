"""Generalisation benchmark of the diagnosis: every truth form of every effect, on every plant,
with the motion channels a user records.

Each effect has at least three truth forms from different physics (its record's ``truths``,
:mod:`diagnosis.benchmark.truths` and :mod:`diagnosis.benchmark.forms`; backlash and GMS in
their own modules), integrated on a grid ten times finer than sampled; positions are
quantised to an encoder count and differentiated as a user would (gradient, backward
differences or a low-passed gradient; 50-1000 counts per sample at the top speed, taken in
turn, :data:`diagnosis.benchmark.runner.MEASURED`). The **sealed** family
(:mod:`diagnosis.benchmark.sealed`, one more form per effect) is written once and run only
with ``--sealed``, at the end of a piece of work, and reported separately. The first thirty-six
sealed families were seen at the ends of sessions 7 to 41 and moved into the open
grid (:mod:`diagnosis.benchmark.seen`, :mod:`diagnosis.benchmark.seen2`,
:mod:`diagnosis.benchmark.seen3`: session 9's, run once on 656e3a8, 39.8 % top-1;
:mod:`diagnosis.benchmark.seen4`: session 10's, run once on d651fad, 34.3 % top-1;
:mod:`diagnosis.benchmark.seen5`: session 10's last, run once on a99721e, 26.1 % top-1;
:mod:`diagnosis.benchmark.seen6`: session 11's, run once on 9155e51, 46.6 % top-1;
:mod:`diagnosis.benchmark.seen7`: session 12's, run once on d12174d, 25.0 % top-1;
:mod:`diagnosis.benchmark.seen8`: session 13's, run once on a2ccae2, 40.3 % top-1;
:mod:`diagnosis.benchmark.seen9`: session 14's, run once on ef5b06a, 33.0 % top-1;
:mod:`diagnosis.benchmark.seen10`: session 15's, run once on 5aa9452, 40.3 % top-1;
:mod:`diagnosis.benchmark.seen11`: session 16's, run once on e33ce5f, 47.7 % top-1;
:mod:`diagnosis.benchmark.seen12`: session 17's, run once on f5cb1e9, 29.5 % top-1;
:mod:`diagnosis.benchmark.seen13`: session 18's, run once on 18bfa60, 17.0 % top-1;
:mod:`diagnosis.benchmark.seen14`: session 19's, run once on 0487306, 36.4 % top-1;
:mod:`diagnosis.benchmark.seen15`: session 20's, run once on ca024ab, 35.8 % top-1;
:mod:`diagnosis.benchmark.seen16`: session 21's, run once on 93064fe, 31.8 % top-1;
:mod:`diagnosis.benchmark.seen17`: session 22's, run once on 5f0e273, 47.2 % top-1;
:mod:`diagnosis.benchmark.seen18`: session 23's, run once on ba95736, 53.4 % top-1;
:mod:`diagnosis.benchmark.seen19`: session 24's, run once on 3cef9aa, 43.8 % top-1;
:mod:`diagnosis.benchmark.seen20`: session 24's other, run once on 5ac3afd, 50.0 % top-1;
:mod:`diagnosis.benchmark.seen21`: session 25's, run once on cead57e, 50.0 % top-1;
:mod:`diagnosis.benchmark.seen22`: session 26's, run once on 72892bf, 48.9 % top-1;
:mod:`diagnosis.benchmark.seen23`: session 27's, run once on 25e7bb5, 51.7 % top-1;
:mod:`diagnosis.benchmark.seen24`: session 28's, run once on 3fa3016, 60.8 % top-1;
:mod:`diagnosis.benchmark.seen25`: session 29's, run once on de40d49, 46.0 % top-1;
:mod:`diagnosis.benchmark.seen26`: session 30's, run once on 00dfbb5, 55.1 % top-1;
:mod:`diagnosis.benchmark.seen27`: session 31's, run once on 5972ebe, 52.8 % top-1;
:mod:`diagnosis.benchmark.seen28`: session 32's, run once on 9f8fda9, 52.8 % top-1;
:mod:`diagnosis.benchmark.seen29`: session 33's, run once on f2c371c, 62.5 % top-1;
:mod:`diagnosis.benchmark.seen30`: session 34's, run once on fe2a59f, 59.7 % top-1;
:mod:`diagnosis.benchmark.seen31`: session 35's, run once on df1f691, 59.7 % top-1;
:mod:`diagnosis.benchmark.seen32`: session 36's, run once on 1264221, 74.4 % top-1;
:mod:`diagnosis.benchmark.seen33`: session 38's, run once on c6080f7, 59.7 % top-1;
:mod:`diagnosis.benchmark.seen34`: session 39's, run once on d7e0374, 64.8 % top-1;
:mod:`diagnosis.benchmark.seen35`: session 40's first, run once on ddc8eb5, 64.2 % top-1;
:mod:`diagnosis.benchmark.seen36`: session 40's other, run once on e20b785, 59.7 % top-1,
below); the present one (one form for each of the ten effects with truths, written in
session 41 by another hand) is sealed: not run. The open grid's latest figures (session 22, below) include
every seen family but seen17, seen18, seen19, seen20, seen21, seen22, seen23, seen24, seen25,
seen26, seen27, seen28, seen29, seen30, seen31, seen32, seen33, seen34, seen35 and seen36.

    python benchmarks/bench_diagnosis_forms.py [--sealed] [--workers N] [--quick]
                                               [--full-protocols] [--checkpoint FILE]
                                               [--sample N [--sample-seed S]] [--keys FILE]
                                               [--json OUT]

Figures: top-1 over all cases and over the detectable ones (an oracle that knows the truth
can tell it from the base fit), clean and out-of-library cases, the mean |shrink error|
(reported gap closed against the truth's), per plant, per effect and per truth form; seconds
per case against one base identification of the plant timed in the same worker.

Session 22 (2026-11-30, code of c6d4a10: ``delay``'s leak only slower than 20 / T,
``drift`` with the heating part; all sixteen seen families, 3372 cases, same seeds; 2327 run
on 2 workers: every drift case and every case where drift had ranked in the top two (722),
and a uniform random 1605 of the other 2650 (a shuffled order, stopped at the session's
end), the figures weighted by stratum): top-1 **51.6 % +- 0.6** (**53.5 % +- 0.6** of the
detectable), mean |shrink error| 0.30, wrong names on 12.9 % +- 0.4 of the effect cases
(in the cases run, 290: drift -> load 28, acceleration -> asymmetry 26, acceleration ->
position 23, inertia -> acceleration 22, gms -> acceleration 16, gms -> delay 14). By plant:
valve 55.5 %, press 54.4 %, isolator 53.4 %, XML-350 53.0 %, damping rig 43.0 %. On session
20's 2340 cases, its figure plus the case-by-case differences of the 1675 of them run:
55.1 % -> 55.4 % (58.3 % -> 58.0 % of the detectable; wrong names 254 -> 260).

Session 20 (2026-11-29, code of 0487306: ``drift`` with a part that builds up and resets;
every case of session 17's 2300 run once, same seeds, in two runs on 2 workers, the drift
cases with seen11 and seen12's (300) and the rest (2040), 1 + 2 workers at times): top-1
**55.3 %** (1272; **58.6 %** of the 2167 detectable), mean |shrink error| 0.288, wrong names
on 250 of 2260 effect cases (11.1 %: gms -> acceleration 26, acceleration -> position 22,
drift -> load 21, inertia -> acceleration 19, acceleration -> asymmetry 12, backlash -> gms
11). By plant: valve 60.8 %, press 59.8 %, isolator 55.9 %, XML-350 55.0 %, damping rig
46.5 %. Against session 19's code (the same cases, assembled from its subset runs: 1259, 54.7
%; 58.0 % of the detectable): the 2040 cases of the other effects all keep their verdicts;
drift 196 -> 209 of its 300 (the oxide film 0 -> 12 of 20, interval lubrication 13 -> 14,
none lost, wrong names 25 -> 25). seen11 to seen14 are not in the figure.

Session 18 (2026-11-29; parts of the grid, paired by key with session 17's full run below,
same seeds; the full grid was not run on this code): ``backlash`` with forces across the play
144 cases 31 -> 43 named, wrong names 31 -> 24; ``inertia`` with masses along the stroke and
with the speed, inertia and acceleration 520 cases 244 -> 250 (wrong 72 -> 74); ``position``
with a smooth force along the stroke, position and drift 468 cases 299 -> 314 (wrong 40 ->
37); gms 156 and asymmetry, delay, position, clean 744 unchanged (55 -> 55, 414 -> 414).
Summed, about 1250 of session 17's 2300 (54.3 %; 57.7 % of the 2167 detectable). seen11 and
seen12 (352 cases) have joined the grid since.

Results of session 17 (2026-11-29, short protocols, code of 005e0e4: ``inertia`` with a
coupled part and a mass trend, joint fits without pinned columns and from alternative
starts; the valve and XML-350 on 1 + 2 workers, the other plants on 2, beside other runs):
the open grid with seen9 and seen10, **2316 cases listed, 2300 run** (16 skipped). Top-1
**52.9 %** (1217; **56.1 %** of the 2167 detectable, 53.9 % counting the 92 delay cases
below a sample as detectable), mean |shrink error| 0.300, wrong names on 245 of 2260 effect
cases (10.8 %: gms -> acceleration 26, drift -> load 21, acceleration -> position 19,
backlash -> gms 15, inertia -> acceleration 15). Clean 0 of 20 named (17 ``none``), ripple 0
of 20. By plant: forging press 59.5 %, valve 58.5 %, XML-350 51.9 %, isolator 51.6 %, damping
rig 44.6 %. On session 15's forms: 1070 of 1940 (58.4 % of the detectable; session 15 had
1038 of 1948, 54.3 %, on other seeds); the seen9 and seen10 forms 147 of 360. Paired with
the same seeds on the valve and XML-350 (code of 41ad387 there, 982 cases): right 529 -> 543,
inertia 71 -> 86 of 100, the other effects 458 -> 457, wrong names 78 -> 77.

Results of session 15 (2026-11-29, short protocols, 2 workers, code of ef5b06a: the
diagnosis simulates every model with a sample at each velocity reversal inside a step,
:func:`diagnosis.composite.simulate_split`; its candidate fits on threads, one per worker
here): the open grid with seen8, **1964 cases listed, 1948 run** (16 skipped), 5329 s wall
(shared for 25 minutes with the sealed and clean runs). Top-1 **53.3 %** (1038; 54.3 % of the
detectable), mean |shrink error| 0.302, wrong names on 179 of 1928 effect cases (9.3 %: gms
-> acceleration 24, acceleration -> position 16, drift -> load 12, backlash -> gms 11,
position -> acceleration 10, load -> drift 9). Clean 0 of 20 named (17 ``none``), ripple 0 of
20. By plant: valve 61.4 %, forging press 58.7 %, isolator 51.6 %, XML-350 49.1 %, damping
rig 46.8 %. The seen8 forms: 72 of 176 (71 when run sealed). The 1772 cases of session 14's
grid (the same forms; the seeds differ, as adding seen8 renumbered them): 966 right on
both codes. By plant there: XML-350 190 -> 204 of 402, where the split matters (its
LuGre's discretisation 1.8 % -> 0.13 % of the force's spread); valve 253 -> 254, damping rig
196 -> 192, forging press 171 -> 164, isolator 156 -> 152 (on those three the split changes
nothing measurable: what moved is the seeds and protocols drawn anew). Asymmetry 115 ->
128/200 (XML-350 12 of 44), drift 144 -> 137, acceleration 82 -> 78; wrong names 137 -> 147.
From the next run on, a case's seed and protocol follow from the case itself
(:func:`diagnosis.benchmark.runner.grid_jobs`), so runs pair case by case.

Results of session 12 (2026-11-28, short protocols, 2 workers): the open grid with seen5,
**1420 cases** (16 skipped), the same seeds before and after. On the session's first code
(7727c9e, session 11's last; 1773 s wall): top-1 **51.1 %** (725; 52.5 % of the
detectable), mean |shrink error| 0.292, wrong names on 78 of 1380 effect cases. On 3dbe5d4
(the starts of ``drift``, ``acceleration`` and ``position`` choose their time scales,
wavelength and defect with the base law's own parameter changes fitted beside them,
:func:`diagnosis.composite.base_basis`; ``gms`` carries the base's ``sigma1`` as its blocks'
micro-damping; 1250 s wall): top-1 **52.3 %** (742; 53.8 % of the detectable), mean
|shrink error| 0.283, wrong names on **68** (4.9 %: gms -> acceleration 14, acceleration ->
position 8, asymmetry -> load 6, backlash -> gms 5, drift -> load 4, acceleration ->
asymmetry 4), clean 0 of 20 named, ripple 0 of 20. Case by case: 30 gained, 13 lost. By
effect: acceleration 51 -> 58/160, drift 91 -> 97/160 (the valve's lubricant step 0 -> 4/4:
its step came where the protocol speeds up and the base's viscous level had taken it), gms
20 -> 25/96 (elasto-plastic presliding 0 -> 9/16; the damping rig's heavily damped base,
which the undamped blocks could not follow at all, 0 -> 3/32), position 99 -> 100/128,
asymmetry 90 -> 89, stribeck_shape 22 -> 21. By plant: damping rig 50.6 -> 53.4 %, valve
52.5 -> 54.4 %, isolator 54.3 -> 55.6 %, press 53.9 -> 53.5 %, XML-350 45.7 -> 45.7 %.
Intermediate (86c0fe9, without position's): 741 (52.2 %), 68 wrong names.

The open grid with seen6 (session 12's end, code of 08b5d32; adding seen6 renumbers the
case seeds, so it compares with the 1420-case figures only in sum): **1596 cases** (16 skipped), top-1 **51.6 %** (823; 52.8 % of the
detectable), mean |shrink error| 0.288, wrong names on 95 of 1556 effect cases (6.1 %: gms
-> acceleration 19, acceleration -> position 12, asymmetry -> load 8, acceleration ->
asymmetry 5, delay -> gms 4, inertia -> acceleration 4), clean 0 of 20 named, ripple 0 of
20; 1351 s wall. The baseline of the next session.

Results of session 13 (2026-11-28; the same 1596 cases and seeds as the baseline above):
on d12174d (the drift's periodic part, the significance against the noise floor where the
gap is >= 3 x it, the acceleration candidate's level part even in a; 1604 s wall) top-1
**56.8 %** (907; 58.2 % of the detectable), mean |shrink error| **0.270**, wrong names on
107 of 1556 effect cases (6.9 %: gms -> acceleration 18, acceleration -> position 12,
inertia -> acceleration 9, asymmetry -> load 8, backlash -> gms 5, acceleration ->
asymmetry 5), clean 0 of 20 named, ripple 0 of 20. Case by case against the baseline: 88
gained, 4 lost. By effect: drift 116 -> 143/180 (humidity cycle 0 -> 17/20, interval
lubrication 0 -> 9/20), acceleration 54 -> 79/180 (rolling skid, moment load and cylinder
pressure 1 -> 25/60), inertia 101 -> 118/180 (the press's mass errors 0 -> 19/36: its two
held-out acceleration events are resolved against the noise), delay 80 -> 86, gms 26 -> 30,
backlash 33 -> 35, stribeck_shape 29 -> 31, asymmetry 96 -> 97, load and position
unchanged. New wrong names: inertia -> acceleration 6 (press forms the mass term and the
level part both reach), load/position -> drift 5 (the periodic part on the valve's
protocol). Re-deciding the baseline's rows offline with the noise statistic alone: 856
(+33), 3 more wrong names. The session's last commit (5bb1dba) adds two fixes that CI's real-data
tests found: the periodic part no longer tries periods at which the motion repeats itself
(EMPS's second record), and the long-record solver leaves pinned extras out. The grid was
not run again on them; its 40 humidity-cycle and interval-lubrication cases, re-run on
5bb1dba, give the same 26 verdicts as on d12174d.

Results of session 14 (2026-11-29; the open grid with seen7, **1788 cases listed**, 1772
run, 16 skipped; adding seen7 renumbers the case seeds, so these compare with the 1596-case
figures above only in sum). On the session's first code (896c69a, session 13's last; 3775 s
wall, shared with other work): top-1 **53.3 %** (945; 54.6 % of the detectable), mean
|shrink error| 0.285, wrong names on 138 of 1732 effect cases (8.0 %: gms -> acceleration
24, acceleration -> position 16, inertia -> acceleration 12, backlash -> gms 7, load ->
drift 5, delay -> gms 5, backlash -> delay 5, asymmetry -> load 5), clean 0 of 20 named (14
``none``, 6 ``unexplained``), ripple 0 of 20 named. On a2ccae2 (significance against the
noise a candidate leaves behind, :func:`diagnosis.verdict.resolved`; the load's memory over
the travel): top-1 **54.5 %** (966; 55.8 % of the detectable), mean |shrink error| 0.284,
wrong names on 137, clean and ripple none named. How these were obtained, as the
session's time allowed: the verdict rule re-decided offline on every row of the first run
(exact: the rows carry the ranked candidates' decision entries; +14, no new wrong name), and
the cases the load's memory can change run again on a2ccae2 - the grid's first 220 cases
(the valve's acceleration, load, asymmetry and stribeck_shape forms) and 199 of the 370 cases
whose effect is ``load`` or whose baseline ranked ``load`` in its first three (the damping
rig's and the press's, the valve's drift and backlash; the isolator's and XML-350's were not
reached and are re-decided only): load plastic_junctions 0 -> 5 (valve 4, damping rig 1),
junction_creep +1, the press's lip_roll and ratchet_texture ``load`` -> ``asymmetry`` (+2),
its hertz_contact s=1 ``load`` -> ``asymmetry`` (-1). By
effect (first run -> a2ccae2): delay 89 -> 96/196, load 152 -> 157/194, inertia 120 ->
122/200, gms 35 -> 37/120, stribeck_shape 35 -> 37/154, asymmetry 112 -> 115/200; the others
unchanged (acceleration 82/200, drift 144/200, position 112/160, backlash 30/108). 500 clean
records on a2ccae2: 0 named (240 ``none``, 260 ``unexplained``, 736 s wall).

Session 16 (parts of the grid; the full grid was not run on this code). A ``delay`` truth
that shifts the force by less than a sample is below the issue's practical size and is counted
apart from the detectable cases (:func:`diagnosis.benchmark.scoring.practical_size`): on
session 15's grid 72 cases, top-1 over the detectable 54.3 % -> 56.3 %. The GMS candidate's
break-away ``tilt`` and wider split: the 137 gms cases of the valve, damping rig and XML-350
(same seeds) 39 -> 47 named, wrong names 26 -> 20; the valve's 460 cases 268 -> 268, wrong
names 36 -> 40 (six other-effect truths now ``gms``). The XML-350 on cc14a5a (seen9 and
seen10 in the grid): 261/522 (50.0 %; 53.8 % of the detectable, 36 delays below a sample),
wrong names 38 (gms -> acceleration 17); on session 15's forms 230/442 against its 217/442.

Session 32 (2026-12-01; ``--sample 272 --sample-seed 1`` of the open grid to seen26, 271
cases and 1 skipped, paired by key; 2 workers): the code of 556a306 145 right (53.5 %; 56.2 %
of the detectable), wrong names 29, mean |shrink error| 0.290; ``position`` with a viscous
drag along the stroke (5972ebe) 146 (53.9 %), wrong names 29, 0.289: one verdict changed (an
XML-350 air-bearing pad, ``unexplained`` -> ``position``). seen26's air-bearing pads (16
cases) on 5972ebe: 14 named (the sealed run on 00dfbb5: 4). 500 clean records on 5972ebe: 0
named (246 ``none``, 254 ``unexplained``). Tried on the same 271 and not kept: a Huber loss
in the joint fits at 3 x the record's noise (the damping rig's base predicts its clean
held-out sinusoid at 1.1 x the true law's NRMSE instead of 1.5 x: four samples at the
triangle's reversals carry 70 % of the true law's squared misfit on its measured
records), 146 -> 145 right, wrong names 29 -> 32; those samples weighed 0 in the joint fits
instead (a velocity step across zero of 10 x the median moving step and 5 % of the top
speed: on the damping rig's triangle and two isolator records only), the damping rig's and
the isolator's 113 cases 55 -> 55 right, wrong names 9 -> 12; the acceleration candidate's
lag started also at 0.1, 0.2 and 0.4 x the motion's time scale, no verdict of the 31
acceleration cases changed.

Session 33 (2026-12-01; session 32's 271 cases again, ``--keys`` of its checkpoint; 2
workers): ``gms`` with a second law variant, four LuGre bristles that nest the base
(5adcaab), 146 -> 147 right, wrong names 29 -> 29, mean |shrink error| 0.291 -> 0.290 (the
damping rig's poroelastic layer named; on the rig's 9 gms truths the candidate closed
-3.09..+0.59 of the excess, now -0.09..+0.59, and over its 69 cases at least -36, now -0.46); the dominance rule of the verdict (ebf5c78: a quarter of the
excess and 3 x every other candidate's, re-decided exactly) 147 -> 151, wrong names 29 ->
30. Out of sample, ``--sample 272 --sample-seed 2`` of the grid to seen27 on a767d98: 148
right, wrong names 25, |shrink error| 0.297; with the dominance rule 151, wrong names 26.
500 clean records on 5adcaab: 0 named (246 ``none``, 254 ``unexplained``); with the rule:
0. Tried and not kept: a compliant mode in ``inertia`` (a mass on a lightly damped spring;
the sample's 24 inertia cases: no verdict changed, a flexible load closed 0.56 -> 0.94);
the acceleration level part through a mode (31 acceleration cases: no verdict changed).

Session 35 (2026-12-01; 2 workers, paired against main on the same keys): ``inertia``'s
mass behind a compliant mode again, as the high-pass ``a s^2 / (s^2 + 2 z w s + w^2)`` of
the measured acceleration, started on a coarse grid of modes and refined around its best
(fe2a59f): session 32's 271 cases 154 -> 156 right (two frame recoils on the isolator,
unexplained before), wrong names 29 -> 29; ``--sample 272 --sample-seed 2`` 159 -> 160 (a
frame recoil on the rig), wrong names 22 -> 22; the 78 inertia and acceleration cases of
both samples and seen29 43 -> 49 (frame recoils and seen29's friction pendulums), wrong
names 9 -> 9; 500 clean records: 0 named (246 ``none``, 254 ``unexplained``).

Session 40 (2026-12-02, code of 8b3fd7f, the diagnosis of d7e0374; ``--sample 300
--sample-seed 40`` of the whole open grid, seen to seen35; 2 workers, alone, 966 s): 299
cases run (1 skipped: a truth short of its size on this motion); of the 297 effect cases
top-1 **60.6 % +- 2.8** (180; **63.7 % +- 2.9** of the 281 detectable), mean |shrink
error| 0.27, wrong names on 36 (12.1 %: inertia -> acceleration 4, asymmetry -> position
3, acceleration -> asymmetry 3); the clean and the out-of-library case not named. By
plant: XML-350 70.3 %, isolator 67.3 %, press 61.4 %, valve 55.6 %, damping rig 52.6 %.

Sealed family of session 40's other writing (``--sealed`` then, written by another hand
without running the diagnosis on it, run once in session 41 on the code of e20b785, session
41's diagnosis code: asymmetry's drag variant added to d7e0374's):
59.7 % top-1;
176 cases, 0 skipped, 638 s wall on 2 workers (alone). Top-1 59.7 % (105;
67.5 % of the 154 detectable; of the 22 undetectable, 8 are delays shifted by less than a
sample (damping rig 2, XML-350 4, isolator 2; 5 named unexplained, 1 asymmetry, 1 drift,
1 delay), 13 below their practical size by the truth's own imprint (asymmetry: forging
press 3, valve 2, damping rig 1, isolator 1, XML-350 1; stribeck_shape: valve 4, XML-350 1)
and 1 forging press asymmetry the oracle does not tell from the base, these 14 all named
none; 1 of the 22 named its effect);
mean |shrink error| 0.271 (0.288 over the detectable, 0.210 over the right ones); wrong
names on 11 (6.2 %): delay -> drift 3 (isolator), inertia -> delay 2 (isolator), and 1
each acceleration -> gms (damping rig), inertia -> position (damping rig), gms -> delay
(damping rig), load -> delay (forging press), delay -> asymmetry (XML-350), backlash -> gms
(XML-350).
By form: position/rust_stain 16/16, load/porous_bushing 19/20, drift/battery_magnet 18/20,
acceleration/slip_coupling 16/20, gms/hanging_shoe 9/12, delay/rolling_shutter 11/20
(10/12 detectable), inertia/scissor_links 7/20, asymmetry/magnetic_conveyor 4/20 (4/11
detectable), stribeck_shape/spin_off 3/16 (3/11 detectable), backlash/swing_shackle 2/12.
By plant: valve 70.0 %, isolator 67.9 %, forging press 64.3 %, XML-350 55.0 %, damping rig
45.0 %.
Now :mod:`diagnosis.benchmark.seen36`, in the open grid; a thirty-seventh family (written
in session 41 by another hand, never run) is the sealed one.

Sealed family of session 40's first writing (``--sealed`` then, written by another hand
without running the diagnosis on it, run once in session 40 on the code of ddc8eb5, the
diagnosis code of d7e0374):
64.2 % top-1;
176 cases, 0 skipped, 651 s wall on 2 workers (alone). Top-1 64.2 % (113;
69.8 % of the 162 detectable; of the 14 undetectable, 6 are delays shifted by less than a
sample (damping rig 2, XML-350 2, isolator 2; 5 named unexplained, 1 none), 7 below their
practical size by the truth's own imprint (valve stribeck_shape 4, forging press
stribeck_shape 3) and 1 forging press stribeck_shape the oracle does not tell from the base,
these 8 all named none; none of the 14 named its effect);
mean |shrink error| 0.226 (0.238 over the detectable, 0.162 over the right ones); wrong
names on 12 (6.8 %): asymmetry -> position 4 (valve), acceleration -> position 4
(isolator), drift -> load 3 (forging press), inertia -> acceleration 1 (damping rig).
By form: load/ball_hysteresis 20/20, inertia/winch_layers 18/20, position/wet_patch 16/16,
drift/leaking_bladder 16/20, acceleration/worm_mesh 14/20, delay/bucket_brigade 13/20
(13/14 detectable), gms/magnet_coupling 8/12, asymmetry/trailing_hose 4/20,
backlash/liquid_bridge 3/12, stribeck_shape/dielectric_pad 1/16 (1/8 detectable). By plant:
isolator 78.6 %, valve 70.0 %, XML-350 67.5 %, forging press 57.1 %, damping rig 50.0 %.
Now :mod:`diagnosis.benchmark.seen35`, in the open grid; a thirty-sixth family (written
in session 40 by another hand, never run) is the sealed one.

Sealed family of session 39's writing (``--sealed`` then, written by another hand without
running the diagnosis on it, run once at the end of session 39 on the code of d7e0374, the
diagnosis code of 606791c):
64.8 % top-1;
176 cases, 0 skipped, 680 s wall on 2 workers (alone). Top-1 64.8 % (114;
69.2 % of the 159 detectable; of the 17 undetectable, 9 are below their practical size by
the truth's own imprint (valve stribeck_shape 3, valve asymmetry 2, forging press
asymmetry 1, forging press stribeck_shape 1, isolator inertia 1, isolator drift 1; all named
none but one valve stribeck_shape, named stribeck_shape), 8 delays shifted by less than a
sample (XML-350 4: 2 named delay, 2 unexplained; damping rig 2: 1 named delay, 1
unexplained; isolator 2: 1 unexplained, 1 none); 4 of the 17 named their effect and count
among the 114);
mean |shrink error| 0.212 (0.220 over the detectable, 0.140 over the right ones); wrong
names on 16 (9.1 %): asymmetry -> stribeck_shape 5, acceleration -> position 4,
inertia -> acceleration 2, inertia -> position 2, load -> delay 1, drift -> load 1,
backlash -> gms 1.
By form: position/grit_band 16/16, load/toggle_clamp 19/20, delay/acoustic_link 15/20,
drift/magnetic_aftereffect 15/20, gms/buckling_strut 8/12, stribeck_shape/floating_pawl
10/16, acceleration/energised_seals 12/20, inertia/yoke_flywheel 11/20,
asymmetry/plunger_pump 5/20, backlash/foam_pads 3/12. By plant: valve 80.0 %, XML-350
67.5 %, forging press 60.7 %, isolator 60.7 %, damping rig 52.5 %.
Now :mod:`diagnosis.benchmark.seen34`, in the open grid; a thirty-fifth family (written
in session 40 by another hand, never run) is the sealed one.

Sealed family of session 38's writing (``--sealed`` then, written by another hand without
running the diagnosis on it, run once at the end of session 38 on the code of c6080f7):
59.7 % top-1;
176 cases, 0 skipped, 605 s wall on 2 workers (alone). Top-1 59.7 % (105;
61.9 % of the 168 detectable; of the 8 undetectable, 6 are below their practical size by the
truth's own imprint (valve stribeck_shape 3, isolator inertia 2, valve asymmetry 1, all
named none), 2 isolator delays shifted by less than a sample (one named delay, the other
none));
mean |shrink error| 0.223 (0.231 over the detectable, 0.150 over the right ones); wrong
names on 35 (19.9 %): asymmetry -> stribeck_shape 7, inertia -> acceleration 4,
backlash -> gms 4, stribeck_shape -> acceleration 4, acceleration -> position 4,
delay -> acceleration 3, load -> delay 2, delay -> gms 2, delay -> inertia 1,
backlash -> delay 1, gms -> delay 1, acceleration -> asymmetry 1, acceleration -> load 1.
By form: position/hardened_zones 16/16, load/magnet_preload 18/20, drift/solenoid_coil
17/20, gms/air_shoe 9/12, acceleration/bowed_screw 13/20, delay/complementary_fusion 12/20,
inertia/shunted_coil 9/20, stribeck_shape/battery_dynamo 6/16, asymmetry/clapper_tool 5/20,
backlash/eddy_gap 0/12. By plant: isolator 67.9 %, valve 62.5 %, XML-350 62.5 %, forging
press 60.7 %, damping rig 47.5 %.
Now :mod:`diagnosis.benchmark.seen33`, in the open grid; a thirty-fourth family (written
in session 39 by another hand, never run) is the sealed one.

Sealed family of session 36's writing (``--sealed`` then, written by another hand without
running the diagnosis on it, run once at the end of session 37 on the code of 1264221, the
diagnosis code of b5696a1):
74.4 % top-1;
176 cases, 0 skipped, 539 s wall on 2 workers (alone). Top-1 74.4 % (131;
75.7 % of the 169 detectable; of the 7 undetectable, 6 are delays below their practical
size (3 of them named delay, 2 unexplained, 1 none), 1 an inertia case (none)); mean
|shrink error| 0.188 (0.189 over the detectable, 0.152 over the right ones); wrong names on
17 (9.7 %): acceleration -> position 4, inertia -> acceleration 3, drift -> load 3,
asymmetry -> stribeck_shape 2, delay -> gms 1, stribeck_shape -> inertia 1,
stribeck_shape -> acceleration 1, gms -> delay 1, load -> delay 1. By form:
position/draining_film 16/16, load/sinking_wiper 19/20, drift/jr_clamp 17/20,
delay/pulsation_comb 16/20, asymmetry/coolant_stream 15/20, inertia/fluid_inerter 14/20,
gms/leaf_pack 8/12, acceleration/nut_liftoff 12/20, stribeck_shape/governor_shoes 8/16,
backlash/dilatant_gap 6/12. By plant: XML-350 87.5 %, valve 80.0 %, isolator 71.4 %,
forging press 67.9 %, damping rig 62.5 %.
Now :mod:`diagnosis.benchmark.seen32`, in the open grid; a thirty-third family (written
in session 37 by another hand, never run) is the sealed one.

Sealed family of session 35's writing (``--sealed`` then, written by another hand without
running the diagnosis on it, run once at the end of session 36 on the code of df1f691, the
diagnosis code of 8f48865):
59.7 % top-1;
176 cases, 0 skipped, 890 s wall on 2 workers (CI ran beside it). Top-1 59.7 % (105;
62.5 % of the 168 detectable; of the 8 undetectable, 6 are delays below their practical
size (5 of them named unexplained, 1 none), 2 stribeck_shape cases (none)); mean
|shrink error| 0.242 (0.246 over the detectable, 0.160 over the right ones); wrong names on
21 (11.9 %): asymmetry -> stribeck_shape 4, drift -> load 4, acceleration -> position 4,
backlash -> gms 3, gms -> delay 2, load -> delay 2, load -> gms 2. By form:
load/wheel_sinkage 16/20, asymmetry/cup_paddle 16/20, drift/frost_layer 16/20,
gms/band_brake 8/12, acceleration/slack_belt 12/20, inertia/magnet_spring 12/20,
delay/disturbance_observer 11/20, position/rack_mesh 8/16,
stribeck_shape/measuring_wheel 4/16, backlash/warming_fit 2/12. By plant: valve 77.5 %,
XML-350 72.5 %, damping rig 50.0 %, isolator 50.0 %, forging press 39.3 %.
Now :mod:`diagnosis.benchmark.seen31`, in the open grid; a thirty-second family (written
in session 36 by another hand, never run) is the sealed one.

Sealed family of session 34's writing (``--sealed`` then, written by another hand without
running the diagnosis on it, run once at the end of session 35 on the code of fe2a59f):
59.7 % top-1;
176 cases, 0 skipped, 420 s wall on 2 workers. Top-1 59.7 % (105;
60.8 % of the 171 detectable; the 5 undetectable are all stribeck_shape cases (4 of them
named none, 1 stribeck_shape)); mean |shrink error| 0.255 (0.183 over the right ones);
wrong names on 27 (15.3 %): acceleration -> asymmetry 5, gms -> delay 5, load -> drift 4,
gms -> position 3, acceleration -> drift 3, inertia -> acceleration 2, backlash -> gms 1,
delay -> stribeck_shape 1, acceleration -> load 1, asymmetry -> stribeck_shape 1,
drift -> position 1. By form: asymmetry/charging_generator 19/20,
drift/carbon_tribolayer 19/20, position/lead_preload 15/16, load/crowned_rollers 16/20,
inertia/liquid_column 15/20, delay/polynomial_smoother 12/20, gms/fibre_wiper 4/12,
backlash/magnet_latch 2/12, stribeck_shape/peel_adhesion 2/16,
acceleration/inertia_lubricator 1/20. By plant: forging press 71.4 %, isolator 71.4 %,
valve 55.0 %, damping rig 55.0 %, XML-350 52.5 %.
Now :mod:`diagnosis.benchmark.seen30`, in the open grid; a thirty-first family (written
in session 35 by another hand, never run) is the sealed one.

Sealed family of session 33's writing (``--sealed`` then, written by another hand without
running the diagnosis on it, run once at the end of session 34 on the code of f2c371c):
62.5 % top-1;
176 cases, 0 skipped, 403 s wall on 2 workers. Top-1 62.5 % (110;
63.5 % of the 170 detectable; the 6 undetectable are all delays below their practical size
(2 of them named delay, 2 unexplained, 2 none)); mean |shrink error| 0.269 (0.216 over the
right ones); wrong names on 23 (13.1 %): acceleration -> asymmetry 6, delay -> acceleration
4, gms -> delay 4, drift -> load 3, load -> delay 2, asymmetry -> load 2, backlash -> gms 1,
inertia -> position 1. By form: position/ferrous_insert 16/16, load/clamping_cylinder
18/20, drift/lining_glazing 16/20, inertia/friction_pendulum 14/20, asymmetry/gecko_wedges
12/20, delay/fixed_point_filter 11/20, gms/hysteresis_brake 6/12,
stribeck_shape/flash_weakening 7/16, acceleration/elastic_counterweight 8/20,
backlash/detent_ball 2/12. By plant: valve 70.0 %, isolator 67.9 %, XML-350 67.5 %,
damping rig 60.0 %, forging press 42.9 %.
Now :mod:`diagnosis.benchmark.seen29`, in the open grid; a thirtieth family (written
in session 34 by another hand, never run) is the sealed one.

Sealed family of session 32's writing (``--sealed`` then, written by another hand without
running the diagnosis on it, run once at the end of session 33 on the code of 9f8fda9):
52.8 % top-1;
176 cases, 0 skipped, 322 s wall on 2 workers. Top-1 52.8 % (93;
56.0 % of the 166 detectable; of the 10 undetectable, 6 are delays below their practical
size (3 of them named acceleration, 1 inertia, 2 unexplained), 4 stribeck_shape cases
(none)); mean |shrink error| 0.300 (0.163 over the right ones); wrong names on 19 (10.8 %):
acceleration -> drift 6, delay -> acceleration 5, gms -> delay 3, acceleration -> position
2, delay -> inertia 1, asymmetry -> load 1, backlash -> gms 1. By form:
load/soft_film_pressure 20/20, asymmetry/angled_pull 18/20, drift/thermostat_cycling 15/20,
inertia/hanging_pendulum 11/20, delay/adaptive_filter 9/20, position/ball_passage 8/16,
stribeck_shape/capillary_condensation 5/16, gms/shear_melting_film 4/12,
backlash/air_cushion_gap 3/12, acceleration/winding_heat 0/20. By plant: valve 70.0 %,
XML-350 62.5 %, isolator 50.0 %, damping rig 42.5 %, forging press 32.1 %.
Now :mod:`diagnosis.benchmark.seen28`, in the open grid; a twenty-ninth family (written
in session 33 by another hand, never run) is the sealed one.

Sealed family of session 31's writing (``--sealed`` then, written by another hand without
running the diagnosis on it, run once at the end of session 32 on the code of 5972ebe):
52.8 % top-1;
176 cases, 0 skipped, 862 s wall on 2 workers. Top-1 52.8 % (93;
55.7 % of the 167 detectable; of the 9 undetectable, 6 are delays (5 of them unexplained,
1 none), 2 stribeck_shape cases (none), 1 a gms case (none)); mean |shrink error| 0.277
(0.208 over the right ones); wrong names on 18 (10.2 %): acceleration -> inertia 8,
asymmetry -> load 4, drift -> load 3, backlash -> gms 1, inertia -> acceleration 1,
stribeck_shape -> asymmetry 1. By form: load/pv_heated_liner 18/20,
inertia/wave_radiation 17/20, position/conductive_strips 16/16, asymmetry/coriolis_slide
15/20, delay/dual_slope_adc 11/20, drift/grease_oil_bleed 8/20,
acceleration/self_loading_drive 3/20, stribeck_shape/suction_pocket 3/16,
backlash/floating_coupling 1/12, gms/wire_mesh_backing 1/12. By plant: isolator 67.9 %,
forging press 57.1 %, valve 50.0 %, damping rig 47.5 %, XML-350 47.5 %.
Now :mod:`diagnosis.benchmark.seen27`, in the open grid; a twenty-eighth family (written
in session 32 by another hand, never run) is the sealed one.

Sealed family of session 30's writing (``--sealed`` then, written by another hand without
running the diagnosis on it, run once at the end of session 31 on the code of 00dfbb5):
55.1 % top-1;
176 cases, 0 skipped, 505 s wall on 2 workers. Top-1 55.1 % (97;
56.9 % of the 167 detectable; of the 9 undetectable, 2 are asymmetry cases (verdict none),
6 delays (2 of them named delay, 3 unexplained, 1 none), 1 a stribeck_shape case (none));
mean |shrink error| 0.312 (0.231 over the right ones); wrong names on 16 (9.1 %):
acceleration -> asymmetry 5, gms -> delay 3, backlash -> gms 2, delay -> gms 1,
stribeck_shape -> drift 1, stribeck_shape -> acceleration 1, load -> delay 1, asymmetry ->
load 1, drift -> load 1. By form: drift/wax_crystallisation 18/20, load/bedded_rail 17/20,
asymmetry/lifting_screw 13/20, inertia/elastomer_mount 13/20, delay/pneumatic_balance
13/20, acceleration/feed_line_surge 8/20, gms/poroelastic_layer 5/12,
stribeck_shape/dwell_squeeze 4/16, position/air_film_flatness 4/16,
backlash/powder_packed_gap 2/12. By plant: isolator 64.3 %, valve 62.5 %, damping rig
57.5 %, XML-350 50.0 %, forging press 39.3 %.
Now :mod:`diagnosis.benchmark.seen26`, in the open grid; a twenty-seventh family (written
in session 31 by another hand, never run) is the sealed one.

Sealed family of session 29's writing (``--sealed`` then, written by another hand without
running the diagnosis on it, run once at the end of session 30 on the code of de40d49):
46.0 % top-1;
176 cases, 0 skipped, 443 s wall on 2 workers. Top-1 46.0 % (81;
48.5 % of the 167 detectable; of the 9 undetectable, 4 are stribeck_shape cases, 4 delays,
1 an inertia case, all with the verdict none); mean |shrink error| 0.294 (0.186 over the
right ones); wrong names on 26 (14.8 %): acceleration -> inertia 8, acceleration ->
asymmetry 4, drift -> load 3, position -> asymmetry 3, gms -> delay 3, position -> delay 2,
acceleration -> drift 2, asymmetry -> load 1. By form: load/constant_flow_pad 19/20,
inertia/oil_column 18/20, drift/additive_settling 17/20, position/cable_reel 9/16,
gms/viscoplastic_overstress 5/12, asymmetry/roller_skew 5/20, delay/interleaved_adc 4/20,
backlash/adhesive_flank 3/12, acceleration/band_capstan 1/20,
stribeck_shape/thermal_closure 0/16. By plant: isolator 53.6 %, valve 50.0 %, forging press
46.4 %, XML-350 42.5 %, damping rig 40.0 %.
Now :mod:`diagnosis.benchmark.seen25`, in the open grid; a twenty-sixth family (written in
session 30 by another hand, never run) is the sealed one.

Sealed family of session 28's writing (``--sealed`` then, written by another hand without
running the diagnosis on it, run once at the start of session 29 on the code of 3fa3016):
60.8 % top-1;
176 cases, 0 skipped, 459 s wall on 2 workers. Top-1 60.8 % (107;
61.3 % of the 173 detectable; of the 3 undetectable, 2 are delays below a sample, 1 a
stribeck_shape case); mean |shrink error| 0.279; wrong names on 15 (8.5 %): acceleration ->
position 4, stribeck_shape -> asymmetry 3, gms -> delay 3, delay -> inertia 1, drift ->
load 1, delay -> position 1, delay -> acceleration 1, gms -> acceleration 1. By form:
drift/pump_down 19/20, load/light_load_skid 18/20, asymmetry/pitching_pads 17/20,
position/track_end 16/16, inertia/qzs_isolator 11/20, delay/force_restoration 9/20,
acceleration/gantry_racking 8/20, gms/eyring_film 4/12, stribeck_shape/wall_slip 3/16,
backlash/graded_clearance 2/12. By plant: valve 85.0 %, XML-350 67.5 %, isolator 64.3 %,
damping rig 52.5 %, forging press 25.0 %. Before the run, the session's engineer had read
this family's form table (the module docstring) while reading the benchmark package; no
change to the diagnosis was made between that reading and the run (the code run differs
from 1c7014e only by two speed changes, verdict-neutral on the 272-case grid).
Now :mod:`diagnosis.benchmark.seen24`, in the open grid; a twenty-fifth family (written in
session 29 by another hand, never run) is the sealed one.

Sealed family of session 27's writing (``--sealed`` then, written by another hand without
running the diagnosis on it, run once at the start of session 28 on the code of 25e7bb5):
51.7 % top-1;
176 cases, 0 skipped, 538 s wall on 2 workers. Top-1 51.7 % (91;
52.9 % of the 170 detectable; the other 6: delays below a sample); mean |shrink error|
0.296; wrong names on 24 (13.6 %): acceleration -> inertia 7, gms -> delay 5, position ->
asymmetry 4, drift -> load 3, inertia -> acceleration 2, asymmetry -> stribeck_shape 1,
acceleration -> position 1, acceleration -> delay 1. By form: drift/oil_evaporation 17/20,
inertia/rocking_block 14/20, delay/swept_grating 13/20, load/disc_spring_pad 11/20,
asymmetry/fluidic_diode 11/20, position/drawer_overhang 10/16, acceleration/belt_creep
5/20, backlash/toggle_spring 4/12, gms/superelastic_flexure 4/12,
stribeck_shape/sommerfeld_journal 2/16. By plant: valve 67.5 %, forging press 50.0 %,
damping rig 47.5 %, isolator 46.4 %, XML-350 45.0 %.
Now :mod:`diagnosis.benchmark.seen23`, in the open grid; a twenty-fourth family (written in
session 28 by another hand, never run) is the sealed one.

Sealed family of session 26's writing (``--sealed`` then, written by another hand without
running the diagnosis on it, run once at the start of session 27 on the code of 72892bf):
48.9 % top-1;
176 cases, 0 skipped, 645 s wall on 2 workers. Top-1 48.9 % (86;
51.2 % of the 168 detectable; the other 8: 6 delays below a sample, 2 Stribeck-shape cases an
oracle cannot tell from the base); mean |shrink error| 0.305; wrong names on 15 (8.5 %):
position -> asymmetry 4, gms -> delay 3, backlash -> gms 2, acceleration -> position 2,
acceleration -> drift 2, asymmetry -> backlash 1, drift -> load 1. By form: load/ball_spin
19/20, inertia/rolling_payload 15/20, acceleration/inertia_valve_damper 14/20,
drift/spall_growth 14/20, delay/quartz_counter 11/20, gms/grease_yield 5/12,
position/crank_transmission 4/16, asymmetry/elliptic_vibration 2/20, backlash/side_loaded_pin
2/12, stribeck_shape/wiping_meniscus 0/16. By plant: valve 67.5 %, isolator 50.0 %, damping
rig 42.5 %, XML-350 42.5 %, press 39.3 %.
Now :mod:`diagnosis.benchmark.seen22`, in the open grid; a twenty-third family (written in
session 27 by another hand, never run) is the sealed one.

Sealed family of session 25's writing (``--sealed`` then, written by another hand without
running the diagnosis on it, run once at the start of session 26 on the code of cead57e):
50.0 % top-1;
176 cases, 0 skipped, 687 s wall on 2 workers (beside a helper's tests and other checks). Top-1 50.0 % (88;
51.2 % of the 168 detectable; the other 8: 6 delays below a sample, 1 load and 1 asymmetry an
oracle cannot tell from the base); mean |shrink error| 0.293; wrong names on 11 (6.3 %, the
fewest of any family): acceleration -> drift 4, gms -> acceleration 2, gms -> delay 2, drift ->
load 1, position -> inertia 1, position -> delay 1. By form: load/pin_in_bore 16/20,
inertia/spring_surge 15/20, delay/magnetoelastic_cell 14/20, position/spool_flow_force 10/16,
acceleration/cone_sensor_brake 9/20, drift/receiver_pressure 9/20, backlash/overlapped_servo
7/12, asymmetry/counterbalance_valve 5/20, gms/contact_renewal 2/12, stribeck_shape/flying_pad
1/16. By plant: valve 67.5 %, isolator 60.7 %, damping rig 45.0 %, press 39.3 %, XML-350
37.5 %.
Now :mod:`diagnosis.benchmark.seen21`, in the open grid; a twenty-second family (written in
session 26 by another hand, never run) is the sealed one.

Sealed family of session 24's other writing (``--sealed`` then, written by another hand
without running the diagnosis on it, run once at the start of session 25 on the code of
5ac3afd): 50.0 % top-1;
176 cases, 0 skipped, 565 s wall on 2 workers (nothing else running). Top-1 50.0 % (88;
54.7 % of the 161 detectable; the other 15: 8 delays below a sample, 5 Stribeck shapes and 2
asymmetries an oracle cannot tell from the base); mean |shrink error| 0.303; wrong names on 16
(9.1 %): delay -> position 4, delay -> inertia 4, acceleration -> position 4 (the isolator's
one-frequency stroke), gms -> delay 2, gms -> acceleration 1, drift -> load 1. By form:
load/heathcote_slip 18/20, drift/grease_channelling 17/20, position/rail_misalignment 16/16,
inertia/friction_damped_mount 15/20, acceleration/rack_flank_sliding 8/20, gms/microslip_bar
6/12, asymmetry/sealing_band 4/20, backlash/wedge_flank 3/12, delay/magnetostrictive_wire 1/20,
stribeck_shape/shear_thinning_oil 0/16. By plant: isolator 60.7 %, valve 60.0 %, XML-350
57.5 %, press 35.7 %, damping rig 35.0 %. Run in a fresh worktree with 5ac3afd's fast-math
normal equations, whose last bits depended on the compile (0a12cc6 made them the same bits).
Now :mod:`diagnosis.benchmark.seen20`, in the open grid; a twenty-first family (written in
session 25 by another hand, never run) is the sealed one.

Sealed family of session 24's writing (``--sealed`` then, written by another hand without
running the diagnosis on it, run once at the end of session 24 on the code of 3cef9aa):
43.8 % top-1;
176 cases, 0 skipped, 977 s wall on 2 workers (beside the README's first command in a
fresh clone and the real-data examples). Top-1 43.8 % (77; 45.2 % of the 168 detectable;
the other 8: 6 delays below a sample, 2 Stribeck shapes an oracle cannot tell from the
base); mean |shrink error| 0.328; wrong names on 35 (19.9 %): acceleration -> asymmetry 4,
load -> inertia 4, delay -> position 4, asymmetry -> delay 4, asymmetry -> position 3,
gms -> acceleration 3, load -> stribeck_shape 3, backlash -> gms 2, acceleration -> delay
2, and five single ones; of the 7 wrong `delay` names, 6 are the code's before the
transducer resonance (308ab2d gives the same), 1 (a backlash case of the damping rig,
`unexplained` before) is the resonance's. By form: drift/film_dewetting 20/20,
position/rail_joint 16/16, delay/gauge_snubber 12/20, load/viscoelastic_rolling 8/20,
inertia/abbe_pitch 8/20, asymmetry/leaning_brush 4/20, gms/slip_weakening 3/12,
acceleration/current_ripple 2/20, stribeck_shape/eddy_brake 2/16,
backlash/grease_packed_gap 2/12. By plant: press 57.1 %, XML-350 50.0 %, valve 42.5 %,
isolator 35.7 %, damping rig 35.0 %.
Now :mod:`diagnosis.benchmark.seen19`, in the open grid; a twentieth family (written in
session 24 by another hand, never run) is the sealed one.

Sealed family of session 23's end (``--sealed`` then, written by another hand without running
the diagnosis on it, run once at the start of session 24 on the code of ba95736, session 23's
last): 53.4 % top-1;
176 cases, 0 skipped, 562 s wall on 2 workers (beside a 1-process helper). Top-1 53.4 %
(94; 55.3 % of the 170 detectable; the other 6: 4 Stribeck shapes and 2 backlash cases an
oracle cannot tell from the base); mean |shrink error| 0.345; wrong names on 20 (11.4 %):
acceleration -> position 4 (the isolator's one-frequency stroke), load -> drift 4,
asymmetry -> stribeck_shape 4, gms -> acceleration 2, and six single ones. By form:
drift/screw_loosening 19/20, position/false_brinelling 16/16, load/ploughing_onset 16/20,
acceleration/ball_train 12/20, asymmetry/running_belt 12/20, inertia/feedforward_lead
12/20, gms/slip_avalanches 5/12, stribeck_shape/bellows_breathing 2/16,
delay/transducer_resonance 0/20, backlash/polymer_gear 0/12. By plant: damping rig 57.5 %,
isolator 57.1 %, XML-350 55.0 %, valve 52.5 %, press 42.9 %.
Now :mod:`diagnosis.benchmark.seen18`, in the open grid; a nineteenth family (written in
session 24 by another hand, never run) is the sealed one.

Sealed family of session 22's end (``--sealed`` then, written by another hand without running
the diagnosis on it, run once on the code of 5f0e273): 47.2 % top-1;
176 cases, 0 skipped, 490 s wall on 2 workers (nothing else running). Top-1 47.2 %
(83; 49.4 % of the 168 detectable; the other 8: 4 delays below a sample, 4 Stribeck
shapes an oracle cannot tell from the base); mean |shrink error| 0.365; wrong names on 16 (9.1 %):
acceleration -> position 4, drift -> position 4, drift -> load 2, gms -> acceleration 2,
and four single ones. By form: load/preload_relief 20/20, position/heated_zone 15/16,
acceleration/aerostatic_tilt 13/20, delay/alpha_beta_tracker 9/20, inertia/screw_stiffness
8/20, asymmetry/felt_lubricator 6/20, gms/junction_growth 6/12, stribeck_shape/
core_loss_drag 3/16, drift/cage_creep 3/20, backlash/mesh_stiffness 0/12. By plant: press
71.4 %, isolator 53.6 %, valve 42.5 %, XML-350 42.5 %, damping rig 35.0 %.
Now :mod:`diagnosis.benchmark.seen17`, in the open grid; an eighteenth family (written in
session 23 by another hand, never run) is the sealed one.

Sealed family of session 21's end (``--sealed`` then, written by another hand without running
the diagnosis on it, run once on the code of 93064fe): 31.8 % top-1;
176 cases, 0 skipped, 518 s wall on 2 workers (beside a 1-process helper). Top-1 31.8 %
(56; 32.2 % of the 174 detectable); mean |shrink error| 0.380; wrong names on 26 (14.8 %):
acceleration -> delay 4, acceleration -> asymmetry 4, load -> asymmetry 4, drift -> load 3,
load -> position 2, gms -> acceleration 2, and six single ones. By form:
position/cam_plunger 15/16, asymmetry/freewheel_roller 11/20, delay/mains_notch 9/20,
load/overhung_load 8/20, gms/power_law_joint 5/12, stribeck_shape/churning_drag 4/16,
drift/tribocharging 3/20, acceleration/jerk_unloading 1/20, inertia/chordal_action 0/20,
backlash/reversing_clutch 0/12. By plant: isolator 50.0 %, press 39.3 %, valve 30.0 %,
XML-350 25.0 %, damping rig 22.5 %.
Now :mod:`diagnosis.benchmark.seen16`, in the open grid; a seventeenth family (written in
session 22 by another hand, never run) is the sealed one.

Sealed family of session 20's end (``--sealed`` then, written by another hand without running
the diagnosis on it, run once on the code of ca024ab): 35.8 % top-1;
176 cases, 0 skipped, 1306 s wall on 1 worker (beside a 2-worker grid run, a 1-worker
clean run and a helper). Top-1 35.8 % (63; 35.6 % of the 174 detectable); mean |shrink
error| 0.318; wrong names on 48 (27.3 %): inertia -> acceleration 8, acceleration ->
asymmetry 8, delay -> acceleration 7, gms -> acceleration 5, drift -> inertia 5, gms -> load
4, stribeck_shape -> acceleration 2, delay -> gms 2, backlash -> delay 2, asymmetry ->
inertia 2. By form: load/jkr_adhesion 19/20, position/gliding_chain 16/16,
asymmetry/belt_idler 10/20, acceleration/swing_arm_roller 7/20,
backlash/bowden_cable 4/12, drift/magnet_heating 4/20, inertia/force_saturation 2/20,
stribeck_shape/thixotropic_grease 1/16, delay/load_cell_creep 0/20,
gms/unloading_microslip 0/12. By plant: valve 45.0 %, damping rig 42.5 %, isolator 39.3 %,
XML-350 35.0 %, press 10.7 %.
Now :mod:`diagnosis.benchmark.seen15`, in the open grid; a sixteenth family (written in
session 21 by another hand, never run) is the sealed one.

Sealed family of session 19's end (``--sealed`` then, written by another hand without running
the diagnosis on it, run once on the code of 0487306): 36.4 % top-1;
176 cases, 0 skipped, 758 s wall on 1 worker (beside a 2-worker grid run). Top-1 36.4 % (64;
40.5 % of the 158 detectable; 14 delay cases below a sample); mean |shrink error| 0.341;
wrong names on 31 (17.6 %): delay -> inertia 7, delay -> position 4, acceleration ->
asymmetry 4, drift -> load 3, acceleration -> position 3, asymmetry -> acceleration 2,
gms -> acceleration 2. By form: load/normal_stress_memory 20/20,
asymmetry/hall_commutation 12/20, drift/shear_degradation 12/20,
stribeck_shape/turbulent_film 7/16, inertia/frame_recoil 7/20,
acceleration/payne_softening 4/20, gms/junction_peeling 2/12, position/curved_guide 0/16,
delay/charge_leakage 0/20, backlash/hydraulic_link 0/12. By plant: XML-350 45.0 %, press
42.9 %, isolator 39.3 %, valve 32.5 %, damping rig 25.0 %.
Now :mod:`diagnosis.benchmark.seen14`, in the open grid; a fifteenth family (written in
session 20 by another hand, never run) is the sealed one.

Sealed family of session 18's end (``--sealed`` then, written by another hand without running
the diagnosis on it, run once on the code of 18bfa60): 17.0 % top-1;
176 cases, 0 skipped, 274 s wall on 2 workers (nothing else running). Top-1 17.0 % (30;
18.5 % of the 162 detectable; 12 delay cases below a sample); mean |shrink error| 0.440;
wrong names on 32 (18.2 %): asymmetry -> position 4, load -> asymmetry 4, drift ->
asymmetry 4, acceleration -> asymmetry 4, asymmetry -> load 3, position -> inertia 3,
stribeck_shape -> asymmetry 2, inertia -> asymmetry 2, gms -> acceleration 2. By form:
position/festoon_cable 13/16, acceleration/sprung_gib 4/20, drift/differential_expansion
4/20, load/scuffing_healing 3/20, stribeck_shape/thermoviscous_film 3/16,
gms/cyclic_hardening 3/12, asymmetry/chip_scraper 0/20, inertia/telescopic_stage 0/20,
delay/lossy_telemetry 0/20, backlash/jaw_coupling 0/12. By plant: XML-350 25.0 %, isolator
17.9 %, valve 17.5 %, damping rig 17.5 %, press 3.6 %.
Now :mod:`diagnosis.benchmark.seen13`, in the open grid; a fourteenth family (written in
session 19 by another hand, never run) is the sealed one.

Sealed family of session 17's end (``--sealed`` then, written by another hand without running
the diagnosis on it, run once on the code of f5cb1e9): 29.5 % top-1;
176 cases, 0 skipped, 1093 s wall on 1 worker (beside two grid runs). Top-1 29.5 % (52;
30.6 % of the 170 detectable; 6 delay cases below a sample); mean |shrink error| 0.359;
wrong names on 28 (15.9 %): inertia -> acceleration 6, load -> asymmetry 5, position ->
acceleration 3, load -> acceleration 3, position -> inertia 2, backlash -> delay 2,
gms -> acceleration 2. By form: acceleration/tilt_wedge 13/20, delay/aerated_load_cell
11/20, inertia/fluid_coupling 9/20, stribeck_shape/readsorption 8/16,
gms/capillary_bridges 5/12, asymmetry/helical_buckling 4/20, drift/particle_ingress 2/20,
load/flash_desorption 0/20, position/beam_sag 0/16, backlash/wire_rope 0/12. By plant:
press 60.7 %, isolator 28.6 %, valve 30.0 %, XML-350 27.5 %, damping rig 10.0 %.
Now :mod:`diagnosis.benchmark.seen12`, in the open grid; a thirteenth family (written in
session 18 by another hand, never run) is the sealed one.

Sealed family of session 16's end (``--sealed`` then, written by another hand without running
the diagnosis on it, run once on the code of e33ce5f): 47.7 % top-1;
176 cases, 0 skipped, 401 s wall on 2 workers (beside a helper's truth sizing). Top-1 47.7 %
(84; 51.5 % of the 163 detectable; 6 delay cases below a sample); mean |shrink error| 0.300;
wrong names on 26 (14.8 %): inertia -> acceleration 13, drift -> load 4, position -> drift 2.
By form: load/full_contact 19/20, asymmetry/chevron_grooves 19/20, drift/zddp_tribofilm
15/20, acceleration/dilatancy_hardening 10/20, position/immersed_plunger 9/16,
inertia/centrifugal_flyweights 4/20, delay/belt_transit 4/20, stribeck_shape/granular_flow
3/16, backlash/harmonic_drive 1/12, gms/asperity_interlocking 0/12. By plant: press 57.1 %,
damping rig 52.5 %, valve 47.5 %, isolator 42.9 %, XML-350 40.0 %. Since (bd055cd, the
inertia candidate's mass growing with the speed) the flyweights are named in 15 of 20.
Now :mod:`diagnosis.benchmark.seen11`, in the open grid; a twelfth family (written in
session 17 by another hand, never run) is the sealed one.

Sealed family of session 15's end (``--sealed`` then, written by another hand without running
the diagnosis on it, run once on the code of 5aa9452): 40.3 % top-1;
176 cases, 0 skipped, 861 s wall beside the open grid. Top-1 40.3 % (71; 42.3 % of the 168
detectable, 40.8 % counting the 6 delay cases below a sample as detectable); mean |shrink
error| 0.346; wrong names on 27 (15.3 %): backlash -> asymmetry 6, delay -> backlash 3,
delay -> acceleration 3, inertia -> asymmetry 3, drift -> load 3. By form:
load/piezoviscous_film 20/20, drift/polymer_swelling 16/20, asymmetry/differential_cylinder
12/20, stribeck_shape/melt_lubrication 9/16, position/bolt_holes 8/16,
gms/kinematic_hardening 5/12, inertia/eddy_coupling 1/20, acceleration/oil_slosh 0/20,
delay/spatial_sampling 0/20, backlash/preloaded_nut 0/12. By plant: press 46.4 %, isolator
42.9 %, valve 40.0 %, XML-350 40.0 %, damping rig 35.0 %.
Now :mod:`diagnosis.benchmark.seen10`, in the open grid; an eleventh family (written in
session 16 by another hand, never run) is the sealed one.

Sealed family of session 14's end (``--sealed`` then, written by another hand without running
the diagnosis on it, run once on the code of ef5b06a, 682 s wall beside the open grid's run):
176 cases (0 skipped), top-1 **33.0 %** (58; 33.3 % of the detectable), mean |shrink error|
0.386, wrong names on 36 (20.5 %: gms -> acceleration 5, acceleration -> asymmetry 4, drift ->
load 4, position -> delay 3, backlash -> gms 3, delay -> acceleration 3, acceleration ->
position 3). By form: meter_out_throttle (asymmetry) 20/20, squeeze_cavitation (load) 16/20,
coating_wear_through (drift) 14/20, dither_averaging (stribeck_shape) 5/16, gouge_fabric
(gms) 3/12, weight_transfer (acceleration) 0/20, air_spring (position) 0/16, pick_and_place
(inertia) 0/20, deadband_reporting (delay) 0/20, magnetic_coupling (backlash) 0/12. By
plant: isolator 39.3 %, forging press 35.7 %, valve 35.0 %, XML-350 35.0 %, damping rig
22.5 %.
Now :mod:`diagnosis.benchmark.seen9`, in the open grid; a tenth family (written in session
15 by another hand, never run) is the sealed one.

Sealed family of session 13's end (``--sealed`` then, written by another hand without running
the diagnosis on it, run once on the code of a2ccae2, 299 s wall): 176 cases (0 skipped),
top-1 **40.3 %** (71; 41.0 % of the detectable), mean |shrink error| 0.324, wrong names on 29
(16.5 %: position -> acceleration 6, acceleration -> asymmetry 4, load -> drift 3, backlash
-> gms 3, gms -> acceleration 3, inertia -> position 2, backlash -> delay 2, gms ->
asymmetry 2). By form: hydrostatic_overload (load) 16/20, sprag_strut (asymmetry) 15/20,
contact_resonance (stribeck_shape) 13/16, running_median (delay) 12/20,
antioxidant_depletion (drift) 11/20, pitch_squeeze (acceleration) 2/20, freewheel_flywheel
(inertia) 2/20, telescopic_cover (position) 0/16, slack_chain (backlash) 0/12, bond_rupture
(gms) 0/12. By plant: forging press 64.3 %, valve 45.0 %, isolator 39.3 %, damping rig
32.5 %, XML-350 27.5 %. Now :mod:`diagnosis.benchmark.seen8`, in the open grid; a ninth
family (written in session 14 by another hand, never run) is the sealed one.

Sealed family of session 12's end (``--sealed`` then, written by another hand without running
the diagnosis on it, run once on the code of d12174d, 179 s wall): 176 cases (0 skipped),
top-1 **25.0 %** (44; 24.7 % of the detectable), mean |shrink error| 0.405, wrong names on 20
(11.4 %: acceleration -> position 4, position -> asymmetry 4, backlash -> asymmetry 3,
acceleration -> inertia 3, gms -> acceleration 2). By form: tilted_pad (asymmetry) 13/20,
plastic_junctions (load) 8/20, motor_attraction (acceleration) 6/20, tomlinson_asperities
(gms) 5/12, rattling_mass (inertia) 5/20, pressure_line (delay) 4/20, rubber_hysteresis
(stribeck_shape) 3/16, end_cushion (position) 0/16, tribo_oxide (drift) 0/20, biased_play
(backlash) 0/12. Now :mod:`diagnosis.benchmark.seen7`, in the open grid.

Sealed family of session 11's end (``--sealed`` then, written by another hand without
running the diagnosis on it, run once on the code of 9155e51, 202 s wall): 176 cases (0
skipped), top-1 **46.6 %** (82; 47.1 % of the detectable), mean |shrink error| 0.332. By
form: pivot_lever (load) 20/20, seal_relaxation (drift) 17/20, oil_pocket (position) 12/16,
starved_film (stribeck_shape) 9/16, spring_return (asymmetry) 8/20, sliding_payload
(inertia) 7/20, slew_limit (delay) 4/20, drag_idler (backlash) 3/12, rate_state_presliding
(gms) 2/12, cylinder_pressure (acceleration) 0/20. Wrong names on 29 of 176 (16.5 %): delay
-> gms 4, asymmetry -> load 4, inertia -> acceleration 4, acceleration -> position 4, gms ->
acceleration 4, delay -> load 2, delay -> position 2, backlash -> acceleration 2, backlash ->
gms 2, delay -> stribeck_shape 1. Now seen: it joins the open grid as
:mod:`diagnosis.benchmark.seen6` (the open grid lists 1612 cases), and a seventh sealed
family is written (176 cases, built and sized only): sealed, not run.

Results of session 11 (2026-11-28, short protocols, 2 workers, 1061 s wall): the grid with
the seen4 forms, **1244 cases** (16 skipped). On the session's first code (6cc3517, 1271 s
wall): top-1 **49.0 %** (609; 50.3 % of the detectable), mean |shrink error| 0.299, wrong
names on 83 of 1204 effect cases (6.9 %: inertia -> acceleration 12, gms -> acceleration 10,
acceleration -> position 8). On bd0f9fa (an acceleration part that is a mass term defers to
``inertia``; a velocity that lags its position is advanced by its measured lag; position's
additive force of the position): top-1 **53.4 %** (664; 54.7 % of the detectable), mean
|shrink error| 0.276, wrong names on **72** (6.0 %: gms -> acceleration 12, position ->
drift 5, acceleration -> asymmetry 5; inertia -> acceleration 0), clean cases named 0 of
20 (14 ``none``, was 12), ripple 0 of 20. Case by case (same seeds): 78 gained, 14 lost
(acceleration -> inertia 2 on the damping rig, slip memory 2, one each elsewhere). By
effect (before -> after): inertia 68 -> 82/140, position 68 -> 83/112 (cogging 0 -> 12/16),
drift 84 -> 91/140, asymmetry 73 -> 80/140, delay 61 -> 65/136, load 121 -> 124/134, gms 16
-> 19/84, stribeck_shape 17 -> 19/106, acceleration 45 -> 45/140, backlash 24 -> 22/72; by
plant the damping rig 44.6 -> 50.4 % and the XML-350 44.3 -> 52.5 % gained most (the
velocity alignment: their backward-differenced records). Still at 0: rolling_skid,
humidity_cycle, eccentric_gear, elastoplastic, bliman_sorine; the forging press's inertia
0/28 (20 cases close a third of the excess or more and are refused for significance: the
held-out gap is two acceleration spikes, encompassing z 1.4-1.6).

The open grid with seen5 (session 11's end, final code; same seeds scheme, so the cases
before seen5 are renumbered): **1420 cases** (16 skipped), top-1 **51.1 %** (725; 52.5 % of
the detectable), mean |shrink error| 0.292, wrong names on 78 of 1380 effect cases (5.7 %:
gms -> acceleration 13, acceleration -> position 8, asymmetry -> load 6, backlash -> gms 5,
acceleration -> asymmetry 5), clean 0 of 20 named, ripple 0 of 20; 1537 s wall.

Sealed family of session 10's end (``--sealed`` then, written by another hand without
running the diagnosis on it, run once on the code of a99721e, 135 s wall): 176 cases (0
skipped), top-1 **26.1 %** (46; 26.7 % of the detectable), mean |shrink error| 0.414. By
form: preload_taper (position) 14/16, ratchet_texture (asymmetry) 10/20, timing_jitter
(delay) 8/20, dispensing_mass (inertia) 6/20, worn_gap (backlash) 3/12, normal_vibration
(load) 2/20, mindlin_contacts (gms) 2/12, eyring_boundary (stribeck_shape) 1/16, moment_load
(acceleration) 0/20, interval_lubrication (drift) 0/20. Wrong names on 15 of 176 (8.5 %):
acceleration -> position 4, gms -> acceleration 4, load -> asymmetry 2, asymmetry -> load
2, inertia -> delay, inertia -> drift, position -> drift 1 each. Now seen: it joins the open
grid as :mod:`diagnosis.benchmark.seen5` (the open grid lists 1436 cases, run once, above),
and a sixth sealed family is written (cylinder_pressure, pivot_lever, spring_return,
starved_film, oil_pocket, sliding_payload, slew_limit, seal_relaxation, drag_idler,
rate_state_presliding; 176 cases, built and sized only): sealed, not run.

Results of session 10 (2026-11-24 15:14 UTC, short protocols, 2 workers, code of commit
d651fad: Delay.MIN_SAMPLES 1.0, the Stribeck speed map and the load's levels inside a
classic LuGre's bristle dynamics at the force level): **1072 cases** (session 9's 896 plus
the seen3 forms' 176; 12 skipped), top-1 **52.7 %** (565; 54.3 % of the detectable), mean
|shrink error| 0.284; clean cases named 0 of 20, ripple 0 of 20; wrong names on 57 of 1032
effect cases (5.5 %): inertia -> acceleration 7, gms -> acceleration 6, asymmetry -> load
6 (the press, where load and direction move together; load -> asymmetry, 11 in session 9,
is gone), acceleration -> asymmetry 5, acceleration -> stribeck_shape 4 (slip memory on
the valve and the press), drift -> load 4, inertia -> position 4. On session 9's 896 cases
**54.1 %** (485, was 457) with 47 wrong names (was 53). By effect (session 9's cases ->
all): load 70/94 -> 101/114, stribeck_shape 2/74 -> 17/90, delay 38/100 -> 59/120. The seen3
forms 80/176 (39.8 % when sealed). On the same grid without the load inside (Q, d651fad's
parent): 559 (52.1 %), 63 wrong names.

Sealed family of session 10 (``--sealed`` then, now :mod:`diagnosis.benchmark.seen4`, written by
another hand without running the diagnosis on it, run once on the code of d651fad, 208 s
wall): 172 cases (4 skipped: clock_skew reaches 0.52/0.68 of the requested size on the
valve and the press), top-1 **34.3 %** (59; 34.9 % of the detectable), mean |shrink error|
0.416. By form: junction_creep (load) 19/20, third_body (drift) 14/20, rod_seal_film
(asymmetry) 12/20, oil_filled_gap (backlash) 6/12, basset_added_mass (inertia) 4/20,
log_weakening (stribeck_shape) 2/16, clock_skew (delay) 2/16, rolling_skid (acceleration)
0/20, cogging (position) 0/16, zener_junction (gms) 0/12. Wrong names on 21 of 172
(12.2 %): inertia -> acceleration 5, acceleration -> position 4, gms -> acceleration 3,
delay -> acceleration 3, asymmetry -> acceleration 2, one each stribeck_shape -> backlash,
inertia -> drift, delay -> asymmetry, drift -> position. Now seen: moved into the open grid
at the end of session 10 (:mod:`diagnosis.benchmark.seen4`), and a new sealed family
written.

Results of session 9 (2026-11-24 12:04 UTC, short protocols, 2 workers, code of commit
656e3a8: the drift's trend chosen by forecasting, ties to the simpler candidate within 5 %):
**896 cases** (the 726 of session 8 plus the session-8 sealed family's 170, now open; 12
skipped), top-1 **51.0 %** (457; 52.9 % of the detectable), mean |shrink error| 0.273;
clean cases named 0 of 20, ripple 0 of 20; wrong names on 53 of 856 effect cases (6.2 %):
load -> asymmetry 11 (the press, confounded), gms -> acceleration 5, inertia ->
acceleration 5, drift -> load 5, acceleration -> inertia 4, acceleration -> asymmetry 4. The
same grid on the session's first code (aa0292c): 445 (49.7 %), 58 wrong names; gained 15
(drift 11, inertia 4), lost 3. By effect: drift 63 -> 72/100, inertia 57 -> 61/100; on the
726 cases of session 8 52.5 % (was 52.3 %); the seen2 forms 76/170 (41.2 % when sealed).

Sealed family of session 9 (``--sealed`` then, now :mod:`diagnosis.benchmark.seen3`, written by
another hand without running the diagnosis on it, run once on the code of commit 656e3a8,
374 s wall): 176 cases (0 skipped), top-1 **39.8 %** (70; 40.9 % of the detectable), mean
|shrink error| 0.388. By form: film_breakdown (load) 18/20, thrust_bearing (asymmetry)
13/20, flash_temperature (acceleration) 11/20, lossy_gearing (inertia) 9/20, fieldbus_hold
(delay) 7/20, bouc_wen (gms) 6/12, transfer_film (position) 5/16, bimodal_roughness
(stribeck_shape) 1/16, humidity_cycle (drift) 0/20, eccentric_gear (backlash) 0/12. Wrong
names on 11 of 176 (6.3 %): position -> drift 4, inertia -> position 2, one each
stribeck_shape -> backlash, position -> stribeck_shape, inertia -> acceleration, load ->
asymmetry, acceleration -> drift. Now seen: moved into the open grid in session 10
(:mod:`diagnosis.benchmark.seen3`), and a new sealed family written.

Session 8:
Results (2026-11-24 07:56 UTC, short protocols, 2 workers, 1058 s wall, code of commit
1bba29f: the encompassing significance test, the acceleration weight's exponent, the
velocity's lag added back to the delay's size, asymmetry's ``vs_neg``): **726 cases** (the
580 of the run before plus the seen family's 146; 6 skipped), top-1 **52.3 %** (54.1 % of
the detectable), mean |shrink error| 0.259; clean cases named 0 of 20, ripple 0 of 20. On
the 580 cases of the forms the run before had, **57.1 %** (331; was 308, 53.1 %; 59.0 % of
the 561 detectable) and mean |shrink error| 0.264. Gains by form (before -> now, same
cases): gms maxwell10 0 -> 5/12, slip_memory 3 -> 6/20, flexible_load 9 -> 12/20,
stribeck_twins 8 -> 10/20, moving_average 5 -> 7/20, impact 0 -> 2/12; losses of one case
in compliant backlash, filtered_acceleration, worn_section. The seen family in the grid:
squeeze_film 16/20, cable_chain 9/20, screw_runout 9/16, direction_curve 8/20,
encoder_latency 4/20, thermal 2/20, film_dynamics 1/20, stiction_spike 0/10. Wrong names on
38 of 686 effect cases (5.5 %): load -> asymmetry 12 (the press: the load candidate closes
0.13 of a Hertzian load gap that direction twins close 0.68 of), inertia -> acceleration 8,
drift -> position 5, acceleration -> position 2, drift -> load 2, gms -> acceleration 2, six
single ones. Still unreached: a Stribeck curve of another shape under a base that frees its
exponent (0/58), frictional memory (3/20) and film dynamics (1/20), elasto-plastic and Dahl
presliding (1/24), an impacting backlash (2/12).

Then (08:45 UTC, 796 s wall, code of commit c477bff): the position candidate is no longer
scored where the held-out positions leave the fit record's stroke. Same top-1 (52.3 %);
the press's five drift cases named ``position`` are now ``load`` twice (its load is
confounded with the record's progress too) and ``unexplained`` three times: 35 wrong names.

The run before (752 s wall, code of commit 3ced1d1, the Diebold-Mariano test): 580 cases,
top-1 53.1 % (54.7 % of the 562 detectable), mean |shrink error| 0.254; 28 wrong names (5 %);
by effect load 51/60, drift 49/60, position 41/48, asymmetry 36/60, inertia 34/60,
acceleration 22/60, delay 21/60, backlash 18/36, gms 3/48, stribeck_shape 0/48; the first
forms (the default benchmark's truths, 99 % on the exact motion) 66 % (116/176).

Sealed family of session 8 (``--sealed`` then, now :mod:`diagnosis.benchmark.seen2`, written by
another hand without running the diagnosis on it, run once on the code of commit 1bba29f,
220 s wall): 170 cases (6 skipped: load_stribeck cannot reach the size on the valve and the
XML-350), top-1 **41.2 %** (42.2 % of the detectable), mean |shrink error| 0.32. By form:
bent_rail (position) 14/16, geared_inertia (inertia) 13/20, sigma_delta (delay) 10/20,
archard_wear (drift) 10/20, contact_aging (acceleration) 9/20, lip_roll (asymmetry) 8/20,
load_stribeck (load) 5/14, spring_loaded (backlash) 1/12, bliman_sorine (gms) 0/12,
film_liftoff (stribeck_shape) 0/16. Wrong names on 25 of 170 (15 %): drift -> position 6,
backlash -> gms 4, acceleration -> asymmetry 3, asymmetry -> position 3, gms -> acceleration
3, stribeck_shape -> acceleration / inertia / drift 3, position -> acceleration 2, inertia
-> acceleration 1. Now seen: the next piece of work moves it into the open grid and writes a
new one. Run again (seen) on c477bff, position not scored beyond the fit stroke: 41.8 %
(71/170), 21 wrong names - the press's archard_wear cases named ``position`` are now
``unexplained`` three times and ``drift`` once.

First sealed family (session 7, run on the code of 3ced1d1, since moved into the open grid as
:mod:`diagnosis.benchmark.seen`): 146 cases, top-1 34.9 % (36.4 % of the detectable), 9
wrong names (6 %), mean |shrink error| 0.30.
"""
import os

# one BLAS thread: a diagnosis's matrices are a few columns wide (see bench_diagnosis.py)
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse  # noqa: E402
import json  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

from diagnosis.benchmark import PLANT_NAMES, format_summary, run_benchmark  # noqa: E402
from diagnosis.benchmark.runner import read_keys  # noqa: E402


def _run(args, strengths, noises, family, keys, kw):
    """The benchmark as the command line asks for it (:func:`run_benchmark`)."""
    return run_benchmark(strengths=strengths, noises=noises, plants=args.plants.split(","),
                         quick=not args.full_protocols, workers=args.workers, forms=family,
                         measured=True,
                         progress=lambda n, info: print(info, flush=True),
                         checkpoint=args.checkpoint, sample=args.sample,
                         sample_seed=args.sample_seed,
                         keys=keys, **kw)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sealed", action="store_true",
                    help="the sealed family only (run once, at the end of a piece of work)")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--quick", action="store_true",
                    help="one strength and noise level")
    ap.add_argument("--full-protocols", action="store_true",
                    help="the plants' full protocols (default: their short ones, 1,400-5,000 "
                         "samples a record, as the clean-record run)")
    ap.add_argument("--plants", default=",".join(PLANT_NAMES))
    ap.add_argument("--effects", default=None, help="comma-separated effects (default: all)")
    ap.add_argument("--checkpoint", default=None,
                    help="JSON-lines file of finished cases; run again with it to resume")
    ap.add_argument("--sample", type=int, default=None,
                    help="a uniform random SAMPLE of the grid's cases only (the same cases "
                         "for the same grid and --sample-seed: two versions of the code "
                         "compared case by case; a family added to the open grid draws "
                         "other cases, so a comparison across one reruns the checkpoint's "
                         "keys, --keys)")
    ap.add_argument("--sample-seed", type=int, default=0)
    ap.add_argument("--keys", default=None,
                    help="run only the cases whose keys this file holds (a checkpoint of "
                         "an earlier run, or one key a line): the same cases again after "
                         "a family joined the grid")
    ap.add_argument("--json", default=None)
    args = ap.parse_args(argv)
    strengths = (1.0,) if args.quick else (0.5, 1.0)
    noises = (0.02,) if args.quick else (0.01, 0.03)
    kw = {} if args.effects is None else {"effects": tuple(args.effects.split(","))}
    family = "sealed" if args.sealed else "all"
    t0 = time.perf_counter()
    try:
        keys = None if args.keys is None else read_keys(args.keys)
    except OSError as exc:
        ap.error(f"--keys: {exc}")
    try:
        res = _run(args, strengths, noises, family, keys, kw)
    except ValueError as exc:
        if not str(exc).startswith(("keys:", "sample")):
            raise
        ap.error(str(exc))      # a bad --keys or --sample: said in one line
    wall = time.perf_counter() - t0
    print(format_summary(res, f"{family} truth forms, measured motion: strengths {strengths}, "
                              f"noise {noises} x std(F), {len(res['rows'])} cases, "
                              f"{len(res['skipped'])} skipped, {wall:.0f} s wall on "
                              f"{args.workers} worker(s)"))
    if args.json:
        with open(args.json, "w") as fh:
            json.dump({k: res[k] for k in ("overall", "per_plant", "per_effect", "per_form",
                                           "rows", "skipped")}, fh, indent=1,
                      default=lambda o: o.item() if isinstance(o, np.generic) else str(o))


if __name__ == "__main__":
    main()
