/* Interleaved A/B timing of two builds of the C runtime (bench/roots_ab.py).
 *
 * The two runtimes are compiled from their own sources with every public
 * symbol renamed (A_... and B_...: -D on the command line) and linked here.
 * Input on stdin, one polynomial per line: FAMILY TMAX DEGREE C0 .. CN (hex
 * floats).  First every polynomial is solved once by each and the answers
 * compared (status, graze flag and root bit for bit); then SWEEPS sweeps, each
 * over every polynomial in an order shuffled anew, calling A and B back to
 * back in an order that alternates, every call timed on its own.  So both
 * see the same machine at the same moment (a neighbour's burst slows both)
 * and the same cold caches and predictors (a solve never follows a solve of
 * the same polynomial by the same build).  The ratio of the two is what a
 * single run can show; absolute times on a shared machine cannot.
 *
 * Output: "# horner8_ns H empty_ns E differ D warm W", then per polynomial
 * "FAMILY NS_A NS_B" (medians over the sweeps, the empty region's cost
 * subtracted), then per differing polynomial "# differ INDEX ...".
 *
 * "roots_ab SWEEPS WARM": B's timed call follows WARM untimed solves of the
 * same polynomial by B (its predictors and caches trained on it, as a solve
 * repeated in a loop finds them); with A and B the same code, B / A is what
 * the stream's cold state costs (bench/roots_ab.py --warm).
 *
 * "roots_ab work A|B|H REPS" (run under valgrind by roots_ab.py
 * --instructions) only reads the polynomials and solves each REPS times by
 * one build (H: evaluates the degree-8 Horner unit REPS times per
 * polynomial instead), printing nothing: the difference between two REPS
 * counts the work of the solves alone, instruction by instruction. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "timing.h"

#define MAXN 16
#define MAXSWEEPS 101

int A_ex(const double c[], int degree, double tmax, double *t, int method, int *graze);
int B_ex(const double c[], int degree, double tmax, double *t, int method, int *graze);

typedef struct {
    char family[32];
    double tmax;
    int degree;
    double c[MAXN + 1];
} Poly;

int main(int argc, char **argv)
{
    int work = argc > 3 && strcmp(argv[1], "work") == 0;
    char which = work ? argv[2][0] : 0;
    int reps = work ? atoi(argv[3]) : 0;
    if (work && (reps < 0 || (which != 'A' && which != 'B' && which != 'H'))) {
        fprintf(stderr, "roots_ab: work A|B|H REPS\n");
        return 2;
    }
    int sweeps = work ? 1 : argc > 1 ? atoi(argv[1]) : 15;
    int warm = !work && argc > 2 ? atoi(argv[2]) : 0; /* B's untimed solves before its timed one */
    if (warm < 0 || warm > 100) {
        fprintf(stderr, "roots_ab: warm must be 0..100\n");
        return 2;
    }
    if (sweeps < 1 || sweeps > MAXSWEEPS) {
        fprintf(stderr, "roots_ab: sweeps must be 1..%d\n", MAXSWEEPS);
        return 2;
    }
    size_t cap = 64, n = 0;
    Poly *ps = malloc(cap * sizeof *ps);
    char line[16384];
    while (ps != NULL && fgets(line, sizeof line, stdin)) {
        if (n == cap) {
            cap *= 2;
            Poly *q = realloc(ps, cap * sizeof *ps);
            if (q == NULL)
                break;
            ps = q;
        }
        Poly *p = &ps[n];
        int got = read_poly_line(line, p->family, &p->tmax, &p->degree, p->c, MAXN);
        if (got < 0) {
            fprintf(stderr, "roots_ab: bad line %zu\n", n + 1);
            return 2;
        }
        n += (size_t)got;
    }
    if (ps == NULL || n == 0) {
        fprintf(stderr, "roots_ab: no polynomials\n");
        return 2;
    }
    if (work) {
        double hc[9] = {1, -2, 3, -4, 5, -6, 7, -8, 1};
        for (int r = 0; r < reps; r++)
            for (size_t i = 0; i < n; i++) {
                double t = 0;
                int g = 0, st = 0;
                if (which == 'H')
                    t = horner8(hc, 0.7);
                else
                    st = which == 'B' ? B_ex(ps[i].c, ps[i].degree, ps[i].tmax, &t, 0, &g)
                                      : A_ex(ps[i].c, ps[i].degree, ps[i].tmax, &t, 0, &g);
                sink = t + st;
            }
        return 0;
    }
    size_t differ = 0;
    for (size_t i = 0; i < n; i++) {
        double ta = 0, tb = 0;
        int ga = 0, gb = 0;
        int sa = A_ex(ps[i].c, ps[i].degree, ps[i].tmax, &ta, 0, &ga);
        int sb = B_ex(ps[i].c, ps[i].degree, ps[i].tmax, &tb, 0, &gb);
        if (sa != sb || (sa == 1 && (ga != gb || memcmp(&ta, &tb, sizeof ta) != 0))) {
            differ++;
            printf("# differ %zu %d %a %d %d %a %d\n", i, sa, ta, ga, sb, tb, gb);
        }
    }
    double *na = malloc(n * (size_t)sweeps * sizeof *na);
    double *nb = malloc(n * (size_t)sweeps * sizeof *nb);
    size_t *order = malloc(n * sizeof *order);
    if (na == NULL || nb == NULL || order == NULL)
        return 2;
    for (size_t i = 0; i < n; i++)
        order[i] = i;
    double overhead = empty_region_ns();
    for (int s = 0; s < sweeps; s++) {
        shuffle(order, n);
        for (size_t k = 0; k < n; k++) {
            const Poly *p = &ps[order[k]];
            for (int w = 0; w < 2; w++) {
                int b = (w + (int)k + s) % 2;
                double t = 0;
                int g = 0;
                for (int r = 0; b && r < warm; r++)
                    sink = B_ex(p->c, p->degree, p->tmax, &t, 0, &g);
                double t0 = now_ns();
                int st = b ? B_ex(p->c, p->degree, p->tmax, &t, 0, &g)
                           : A_ex(p->c, p->degree, p->tmax, &t, 0, &g);
                double t1 = now_ns();
                sink = t + st;
                (b ? nb : na)[order[k] * (size_t)sweeps + (size_t)s] = t1 - t0 - overhead;
            }
        }
    }
    /* the unit: one degree-8 Horner evaluation, 16 in a row, each waiting
     * for the last (as bench/roots_harness.c) */
    double hc[9] = {1, -2, 3, -4, 5, -6, 7, -8, 1}, hns[2001];
    for (int r = 0; r < 2001; r++) {
        double v = 0;
        double t0 = now_ns();
        for (int h = 0; h < 16; h++)
            v = horner8(hc, 0.7 + v * 0.0);
        double t1 = now_ns();
        sink = v;
        hns[r] = (t1 - t0 - overhead) / 16;
    }
    printf("# horner8_ns %.2f empty_ns %.2f differ %zu warm %d\n", median(hns, 2001), overhead,
           differ, warm);
    for (size_t i = 0; i < n; i++)
        printf("%s %.2f %.2f\n", ps[i].family, median(&na[i * (size_t)sweeps], sweeps),
               median(&nb[i * (size_t)sweeps], sweeps));
    return 0;
}
