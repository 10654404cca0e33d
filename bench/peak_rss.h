/* The process's peak resident set size so far, in KiB (getrusage's
 * ru_maxrss): what the memory benchmarks print before and after a draw. */
#ifndef GLFX_BENCH_PEAK_RSS_H
#define GLFX_BENCH_PEAK_RSS_H

#include <sys/resource.h>

static long peak_rss_kib(void) {
    struct rusage u;
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss;
}

#endif
