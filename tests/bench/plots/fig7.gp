# fig7.gp: the paper's Fig. 7 from fig7.dat (columns: NCs, board, replay in
# paper mode, replay as the board runs by default, the tuned what-if):
# speed-up over 1 NC above, efficiency (speed-up / NCs) below.
#   gnuplot -e "dat='docs/figures/fig7.dat'; out='docs/figures/fig7.png'; size='512x480'" tests/bench/plots/fig7.gp
set terminal pngcairo size 820,900 font ",10"
set output out
set multiplot layout 2,1 title sprintf("Fig. 7: demo.scn %s on equal-speed unit computers", size)
set logscale x 2
set xrange [0.8:320]
set grid
set key outside bottom center horizontal maxrows 3 width -2
set style line 1 lt 1 lc rgb "#009e73" pt 7 lw 1.5
set style line 2 lt 1 lc rgb "#56b4e9" pt 5 lw 1.5
set style line 3 lt 1 lc rgb "#e69f00" pt 9 lw 2
set style line 4 dt 3 lc rgb "#555555" lw 1.5

set ylabel "speed-up over 1 NC"
set logscale y 2
set yrange [0.8:320]
set format x ""
plot x title "linear" with lines dt 2 lc rgb "gray", \
     dat using 1:2 title "board (largest NC's instructions)" with linespoints ls 1, \
     dat using 1:3 title "replay, paper mode (the reproduction)" with linespoints ls 2, \
     dat using 1:4 title "replay, the board's default (ask ahead)" with linespoints ls 3, \
     dat using 1:5 title "what-if: tuned K and factor, pipelined" with lines ls 4, \
     "-" using 1:2 title "LINKS-1 (paper): 63.07x at 64 NCs" with points pt 3 ps 2 lc rgb "red"
64 63.07
e

set format x "%g"
set xlabel "NCs"
set ylabel "efficiency (speed-up / NCs)"
unset logscale y
set yrange [0:1.05]
set key inside bottom left vertical
plot dat using 1:($2/$1) title "board" with linespoints ls 1, \
     dat using 1:($3/$1) title "replay, paper mode" with linespoints ls 2, \
     dat using 1:($4/$1) title "replay, the board's default" with linespoints ls 3, \
     dat using 1:($5/$1) title "what-if: tuned" with lines ls 4, \
     "-" using 1:2 title "LINKS-1 (paper)" with points pt 3 ps 2 lc rgb "red"
64 0.9855
e
unset multiplot
