/* grinding.c: grinding a feed with rates typed in (docs/grinding.md). A feed
 * of 2 kg in the coarsest of 16 √2 classes below 4 mm is ground for 10
 * minutes; the appearance function comes from the JKMRC model at one impact
 * energy. The rates, the model's A and b and its t-family table are
 * illustrative numbers, not an ore's: use your ore's laboratory results.
 * Prints P80 and the specific energy at a power draw of 50 W. */
#include <math.h>
#include <stdio.h>

#include <demill.h>

enum { N = 16 };

static int check(demill_grinding *g, demill_status s, const char *what)
{
    if (s != DEMILL_OK)
        fprintf(stderr, "%s: %s (%s)\n", what, demill_grinding_last_error(g), demill_strerror(s));
    return s != DEMILL_OK;
}

int main(void)
{
    demill_grinding *g;
    if (demill_grinding_create(0.004, N, &g) != DEMILL_OK)
        return 1;
    double limits[N + 1], feed[N] = {2.0}, rates[N];
    /* rows of t10, t2, t4, t25, t50, t75 in % (illustrative) */
    const double table[3 * 6] = {10, 30, 18, 4.5, 2.5, 2.0, 20, 50, 33, 9.0, 5.0, 4.0,
                                 30, 65, 46, 13.5, 7.5, 6.0};
    int bad = check(g, demill_grinding_sizes(g, limits, N + 1, NULL), "sizes");
    /* S_i = 0.01 (x_i / 1 mm)^0.8 1/s at the class's upper limit x_i; the
     * sink does not break */
    for (int i = 0; i < N; i++)
        rates[i] = i == N - 1 ? 0.0 : 0.01 * pow(limits[i] / 0.001, 0.8);
    bad = bad || check(g, demill_grinding_set_feed(g, N, feed), "feed");
    bad = bad || check(g, demill_grinding_set_rates(g, N, rates), "rates");
    bad = bad || check(g, demill_grinding_set_jk(g, 60, 1.0, 3, table), "JKMRC model");
    /* impacts of 0.1 kWh/t = 360 J/kg */
    bad = bad || check(g, demill_grinding_set_appearance_energy(g, 360), "appearance");
    for (int minute = 1; !bad && minute <= 10; minute++) {
        double p80, kwh_t;
        bad = check(g, demill_grinding_run(g, 60), "run") ||
              check(g, demill_grinding_size_passing(g, 0.8, &p80), "P80") ||
              check(g, demill_grinding_specific_energy(g, 50, 2.0, &kwh_t), "energy");
        if (!bad)
            printf("%2d min: P80 %.3f mm, %.2f kWh/t\n", minute, 1000 * p80, kwh_t);
    }
    demill_grinding_destroy(g);
    return bad;
}
