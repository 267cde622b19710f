/* The C library of tests/externals/c_forms. */
double stats_mean(const double *xs, int n);
void stats_scale(double *xs, int n, double factor);
