#include "stats.h"

double stats_mean(const double *xs, int n) {
    double sum = 0;
    for (int i = 0; i < n; i++)
        sum += xs[i];
    return n > 0 ? sum / n : 0;
}

void stats_scale(double *xs, int n, double factor) {
    for (int i = 0; i < n; i++)
        xs[i] *= factor;
}
