# Weak-scaling model of a distributed run from its measured halo traffic (bench/mpi/run.sh).
# Inputs (-v): name (the case), loop1 (loop seconds of the serial run, one thread), steps, particles (its count);
# from the 2-rank run: halo (halo particles over owned), bytes (halo bytes per particle per rate
# evaluation: a rate evaluation of impactSph, a stage of tlSph) and messages (per rank per
# evaluation). At 2 ranks each rank has one cut face and
# one neighbour rank.
#
# Weak scaling keeps n = particles/2 per rank and the rank's block the shape it has at 2 ranks;
# recursive coordinate bisection of P = 2^k ranks cuts axis a (cycling x, y, z) c_a times, so an
# interior rank has f = sum_a min(2, c_a) faces and nb = prod_a (1 + min(2, c_a)) - 1 neighbour
# ranks (faces, edges and corners: its halo box reaches them all). Per evaluation a rank sends
# bytes * n * f bytes in messages * nb messages, and takes part in `reductions` global reductions
# (gathers of log2 P rounds). Time: t_comm = messages * nb * alpha + bytes * n * f / beta
# + reductions * log2(P) * alpha, against t_comp = loop1 / steps * n / particles. alpha and beta are
# assumptions, not measurements: a cluster interconnect's 1.5 us latency and 5 GB/s per rank.
BEGIN {
    alpha = 1.5e-6; beta = 5e9; reductions = 12
    n = particles / 2
    tcomp = loop1 / steps * n / particles
    printf "\nWeak-scaling model of %s (n = %d particles per rank, t_comp %.3g s per evaluation; alpha %.2g s, beta %.2g B/s, %d reductions per evaluation; measured at 2 ranks: halo %.3g of the owned, %.4g B per particle, %.3g messages per rank per evaluation)\n\n", name, n, tcomp, alpha, beta, reductions, halo, bytes, messages
    print "| ranks | faces per rank | neighbour ranks | halo / owned | bytes per rank per evaluation | t_comm / t_comp | predicted efficiency |"
    print "|---:|---:|---:|---:|---:|---:|---:|"
    for (k = 1; k <= 6; ++k) {
        P = 2 ^ k
        f = 0; nb = 1
        for (a = 0; a < 3; ++a) {
            c = int((k - a + 2) / 3); if (c < 0) c = 0
            m = c < 2 ? c : 2
            f += m; nb *= 1 + m
        }
        nb -= 1
        tcomm = messages * nb * alpha + bytes * n * f / beta + reductions * k * alpha
        printf "| %d | %d | %d | %.3g | %.4g | %.3g | %.3f |\n", P, f, nb, halo * f, bytes * n * f, tcomm / tcomp, tcomp / (tcomp + tcomm)
    }
}
