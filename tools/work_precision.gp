# Work-precision plot from bench/work_precision's CSV: one log-log panel per scene, error against
# run time. Points are single settings at their median run time, with the spread over the runs as
# horizontal bars; the line through an engine's points is its best error for a given run time (the
# Pareto front: sorted by median run time, each point better than all cheaper ones).
#
# Usage: gnuplot -c tools/work_precision.gp docs/work_precision.csv docs/work_precision.png
csv = ARG1 eq "" ? "docs/work_precision.csv" : ARG1
png = ARG2 eq "" ? "docs/work_precision.png" : ARG2

set terminal pngcairo size 2000,2300 font "DejaVu Sans,12" linewidth 1.5
set output png
set datafile separator ","
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set grid xtics ytics mxtics mytics lc rgb "#e4e4e4" lw 0.6
set tics nomirror
set xlabel "run time of the scene (s, median and spread over the runs)" offset 0,0.4
set ylabel "max position error (m)" offset 1.5,0
set key top right spacing 1.1 samplen 2 font ",10" box opaque

# Exact zeros (resting bodies) cannot sit on a log axis: drawn at the floor.
floor = 1e-10
err(e) = e > floor ? e : floor

# Rows of one engine and scene; and the same rows sorted by run time, keeping only those that beat
# every cheaper one.
rows(engine, scene) = sprintf("< awk -F, '$1==\"%s\" && $3==\"%s\"' %s", engine, scene, csv)
front(engine, scene) = rows(engine, scene) . " | sort -t, -k9,9g | awk -F, 'NR==1 || $5<best {best=$5; print}'"
# The engines' usual settings: Box2D v8p3 and Chipmunk it10 at 60 Hz, Platon 1024 units/m at 60 Hz.
usual(engine, scene, setting) = rows(engine, scene) . sprintf(" | awk -F, '$2==\"%s\" && $4>0.0166 && $4<0.0167'", setting)

set style line 1 lc rgb "#1f5fbf" pt 7 ps 0.7 lw 2   # Platon
set style line 2 lc rgb "#d0312d" pt 5 ps 0.7 lw 2   # Box2D
set style line 3 lc rgb "#2e9b3a" pt 9 ps 0.8 lw 2   # Chipmunk
set style line 4 lc rgb "#1f5fbf" pt 7 ps 0.7 lw 2   # warp 90
set style line 5 lc rgb "#8a2be2" pt 5 ps 0.7 lw 2   # warp 120
set style line 6 lc rgb "#e08000" pt 9 ps 0.8 lw 2   # warp 252

set multiplot layout 6,3 title "Work-precision: error against run time (log-log). Points: one setting each (Platon: 64-4096 units/m x 30-240 Hz; Box2D: v1p1-v20p8 x 30-240 Hz; Chipmunk: 1-30 iterations x 30-240 Hz).\nLines: best error for the run time (Pareto front). Large marks: the usual settings (Platon 1024 u/m, Box2D v8p3, Chipmunk it10, all 60 Hz). Errors of exactly 0 drawn at 10^{-10} m." font ",13"

titles = "flight:free flight, 1.5 s (parabola)|landing:landing from 2 m (own resting height)|slope10:frictionless slope 10°, 2 s (along the slope)|slope30:frictionless slope 30°, 2 s|slope45:frictionless slope 45°, 2 s|slope60:frictionless slope 60°, 2 s|chain:running 10 m/s over 1,000 collinear segments, 45 s|rest:resting on a floor from its own rest pose, 10^6 frames|bounce10:elastic bounce: apex after 10 bounces|bounce100:elastic bounce: apex after 100 bounces|ramp:run-up: speed set every frame by the game|circle:velocity turned every frame (2 m circle)|slopechange:sliding into a 20° rise met inside a frame"
scenes = "flight landing slope10 slope30 slope45 slope60 chain rest bounce10 bounce100 ramp circle slopechange"
title_of(s) = (i = strstrt(titles, s . ":"), t = titles[i + strlen(s) + 1:], j = strstrt(t, "|"), j > 0 ? t[1:j - 1] : t)

do for [k = 1:words(scenes)] {
  s = word(scenes, k)
  set title title_of(s) font ",12"
  if (k > 1) { unset key } else { set key }
  plot \
    rows("Platon", s) using 9:(err($5)):10:11 with xerrorbars ls 1 pt 6 notitle, \
    front("Platon", s) using 9:(err($5)) with linespoints ls 1 title "Platon", \
    usual("Platon", s, "1024u/m") using 9:(err($5)) with points ls 1 ps 2.2 notitle, \
    rows("Box2D 2.4.1", s) using 9:(err($5)):10:11 with xerrorbars ls 2 pt 4 notitle, \
    front("Box2D 2.4.1", s) using 9:(err($5)) with linespoints ls 2 title "Box2D 2.4.1", \
    usual("Box2D 2.4.1", s, "v8p3") using 9:(err($5)) with points ls 2 ps 2.2 notitle, \
    rows("Chipmunk 7.0.3", s) using 9:(err($5)):10:11 with xerrorbars ls 3 pt 8 notitle, \
    front("Chipmunk 7.0.3", s) using 9:(err($5)) with linespoints ls 3 title "Chipmunk 7.0.3 (debug build)", \
    usual("Chipmunk 7.0.3", s, "it10") using 9:(err($5)) with points ls 3 ps 2.2 notitle
}

# Warps: Platon only, one line per edge angle.
set key
do for [variant in "walk float"] {
  suffix = variant eq "walk" ? "" : "-float"
  set title (variant eq "walk" ? "Platon walking across warp edges, 2.5 s (7 m: stopped at edge)" : "Platon floating across warp edges, no floor, 2.5 s") font ",12"
  plot \
    rows("Platon", "warp90" . suffix) using 9:(err($5)) with points ls 4 pt 6 notitle, \
    front("Platon", "warp90" . suffix) using 9:(err($5)) with linespoints ls 4 title "90° (cube)", \
    rows("Platon", "warp120" . suffix) using 9:(err($5)) with points ls 5 pt 4 notitle, \
    front("Platon", "warp120" . suffix) using 9:(err($5)) with linespoints ls 5 title "120° (tetrahedron)", \
    rows("Platon", "warp252" . suffix) using 9:(err($5)) with points ls 6 pt 8 notitle, \
    front("Platon", "warp252" . suffix) using 9:(err($5)) with linespoints ls 6 title "72+180° (dodecahedron)"
}
# Gap and penetration per scene with a floor: every setting of each engine, side by side.
contact = "landing slope10 slope30 slope45 slope60 chain rest slopechange"
byScene(engine, column) = sprintf("< awk -F, -v list='%s' 'BEGIN {n = split(list, s, \" \"); for (i = 1; i <= n; ++i) at[s[i]] = i} $1==\"%s\" && ($3 in at) {print at[$3] \",\" $%d}' %s", contact, engine, column, csv)
set xrange [0.5:words(contact) + 0.5]
set xtics ("landing" 1, "slope10" 2, "slope30" 3, "slope45" 4, "slope60" 5, "chain" 6, "rest" 7, "slopechange" 8) font ",10"
unset logscale x
set format x "%g"
set xlabel ""
set key top left
do for [column in "7 6"] {
  set ylabel (column eq "7" ? "gap left at the end (m)" : "deepest penetration (m)") offset 1.5,0
  set title (column eq "7" ? "gap to the nearest line at the end, all settings" : "deepest penetration over all frames, all settings") font ",12"
  plot \
    byScene("Platon", column + 0) using ($1 - 0.2):(err($2)) with points ls 1 pt 6 title "Platon", \
    byScene("Box2D 2.4.1", column + 0) using 1:(err($2)) with points ls 2 pt 4 title "Box2D 2.4.1", \
    byScene("Chipmunk 7.0.3", column + 0) using ($1 + 0.2):(err($2)) with points ls 3 pt 8 title "Chipmunk 7.0.3"
}
unset multiplot
