#!/usr/bin/env bash
# Plots a run's thickness profile over Evans-Fung (both from shape_profile.csv), and
# the inner surface's sheets: the fluid left between the faces.
# Usage: bash examples/rbc/plot_profile.sh RUN_DIR OUT.png
set -euo pipefail
run=$1; png=$2
gnuplot <<EOF
set datafile separator ","
set terminal png size 900,600
set output "$png"
set grid
set xlabel "r [um]"
set ylabel "axial position [um]"
set key outside below
plot "$run/shape_profile.csv" every ::1 using (\$1*1e6):(\$3*1e6) with linespoints lc 1 title "simulated top", \
     "" every ::1 using (\$1*1e6):(\$4*1e6) with linespoints lc 1 dt 2 title "simulated bottom", \
     "" every ::1 using (\$1*1e6):(\$5*0.5e6) with lines lc 2 lw 2 title "Evans-Fung (same D), +-T/2", \
     "" every ::1 using (\$1*1e6):(-\$5*0.5e6) with lines lc 2 lw 2 notitle, \
     "" every ::1 using (\$1*1e6):(\$6*1e6) with linespoints lc 3 pt 6 title "simulated inner surface (fluid between)", \
     "" every ::1 using (\$1*1e6):(\$7*1e6) with linespoints lc 3 pt 6 notitle
EOF
