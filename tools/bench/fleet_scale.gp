# Figures of the fleet sweep (tools/bench/fleet_scale.sh; issue 15 section 5, scale in robots).
#
#   gnuplot -e "csv='docs/perf/fleet_scale.csv'; png='fleet_scale.png'" tools/bench/fleet_scale.gp
#
# Left: lockstep steps/s against N, per vendor and grouping. Middle: the lockstep cost of one
# step (1/steps_per_s, ms) against N with its least-squares line a + b N (linear cost: the
# points lie on it). Right: realtime at 100 Hz, deadline misses (loop overruns) plus stale
# input reads of all processes against N, one point per run (0 is plotted at 0.5 on the log axis).
if (!exists("csv")) csv = 'docs/perf/fleet_scale.csv'
if (!exists("png")) png = 'fleet_scale.png'
set terminal pngcairo size 1500,480 font ",10"
set output png
set datafile separator ","
set key top left box opaque
set grid
set xrange [0:105]
set multiplot layout 1,3 title "plexus fleet of unicycles (fleet\\_unicycles.sh N GROUPING, 100 Hz, RFID output feedback), 2-core shared machine"

series = "cyclone,type cyclone,robot fast,type fast,robot"
vend(s) = s[1:strstrt(s, ",") - 1]
grp(s) = s[strstrt(s, ",") + 1:]
sel(mode, s, v) = (strcol(1) eq mode && strcol(2) eq vend(s) && strcol(3) eq grp(s) && strcol(7) ne "" && v == v) ? v : NaN
label(s) = vend(s) . ", by " . grp(s)

set title "lockstep: steps/s"
set xlabel "robots N"
set ylabel "steps/s"
set logscale y
plot for [i=1:words(series)] csv using 4:(sel("lockstep", word(series, i), column(8) > 0 ? column(8) : NaN)) every ::1 with linespoints lc i title label(word(series, i))
unset logscale y

set title "lockstep: wall time of one step, and its fit a + b N (log scale)"
set ylabel "ms per step"
set logscale y
set fit quiet logfile '/dev/null'
fitted = ""
do for [s in series] {
  a = 1; b = 0.1; undefine STATS_*
  stats csv using 4:(sel("lockstep", s, column(8) > 0 ? 1000.0 / column(8) : NaN)) every ::1 nooutput
  if (exists("STATS_records") && STATS_records >= 2) {
    fit a + b * x csv using 4:(sel("lockstep", s, column(8) > 0 ? 1000.0 / column(8) : NaN)) every ::1 via a, b
    fitted = fitted . sprintf("%s: %.3g + %.3g N ms\n", label(s), a, b)
    eval sprintf("a_%s = %.6g; b_%s = %.6g", vend(s) . "_" . grp(s), a, vend(s) . "_" . grp(s), b)
  }
}
print "fit of the lockstep cost per step:\n" . fitted
set label 1 fitted at graph 0.3, graph 0.2 left front
key(s) = vend(s) . "_" . grp(s)
plot for [i=1:words(series)] csv using 4:(sel("lockstep", word(series, i), column(8) > 0 ? 1000.0 / column(8) : NaN)) every ::1 with points pt 7 lc i title label(word(series, i)), \
     for [i=1:words(series)] (exists("a_" . key(word(series, i))) ? value("a_" . key(word(series, i))) + value("b_" . key(word(series, i))) * x : NaN) with lines dt 2 lc i notitle
unset label 1
unset logscale y

set title "realtime, 100 Hz, 20 s runs: deadline misses + stale input reads"
set xrange [0:105]
set key bottom right
set ylabel "overruns + stale reads (all processes)"
set logscale y
set yrange [0.4:*]
plot for [i=1:words(series)] csv using 4:(sel("realtime", word(series, i), (column(11) + column(12)) > 0 ? column(11) + column(12) : 0.5)) every ::1 with points pt 7 ps 1.2 lc i title label(word(series, i))
unset multiplot
