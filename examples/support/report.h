/* Shared by the section examples: command-line options, the verdict rule,
 * and one row format printed either as an aligned table or as CSV. */
#ifndef MCSPEC_EXAMPLE_REPORT_H
#define MCSPEC_EXAMPLE_REPORT_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

typedef struct {
    size_t n;              /* bins N */
    size_t k;              /* samples per trial K */
    unsigned long trials;  /* trials per measured quantity */
    uint64_t seed;         /* PCG32 initstate; the stream is fixed */
    int csv;               /* print CSV instead of a table */
} ex_options;

/* What ex_parse_options returns: go on, or the exit status for main. */
enum { EX_PARSE_OK = -1, EX_PARSE_HELP = 0, EX_PARSE_ERROR = 2 };

/* Parses --n N, --k K, --trials T, --seed S, --csv, --help (also --opt=V).
 * *opt holds the defaults on entry. max_n bounds --n, max_k bounds --k. On
 * --help prints `help` to stdout and returns EX_PARSE_HELP; on a bad option
 * prints the problem and the usage to stderr and returns EX_PARSE_ERROR.
 * Both are the status main returns, so main reads
 *     if (rc != EX_PARSE_OK) return rc; */
int ex_parse_options(int argc, char **argv, ex_options *opt, size_t max_n, size_t max_k,
                     const char *help);

/* Takes an example's own string option "--name VALUE" or "--name=VALUE" out
 * of argv (shifting the rest down, *argc reduced) before ex_parse_options
 * sees it: 1 with *value set if present, 0 if absent, -1 (after a usage
 * message on stderr) if its value is missing. */
int ex_take_option(int *argc, char **argv, const char *name, const char **value);

/* The rounding floor of a Var[I] row for f[n] and K: 1e-12 of the variance
 * v (at least 1e-24), and at least 1e-15 of E[f^2]/K, the size of the second
 * moments a variance is formed from, so a variance of 0 that some route
 * rounds to 1e-19 reads 0 (verdict holds, z 0). */
double ex_variance_floor(size_t n, size_t k, const double *f, double v);

/* The integrand the sections share: a smooth wave plus an edge at x = 0.3,
 * 0.5 + 0.3 sin(2 pi x) + 0.4 [x >= 0.3]. */
double ex_integrand(double x);
/* f[n] = ex_integrand at the centre of each of n bins. */
void ex_integrand_bins(size_t n, double *f);

/* Text every --help shows after the example's own description. */
extern const char ex_verdict_rules[];
extern const char ex_common_usage[];

/* Field that does not apply: EX_NA for a double, EX_NO_FREQ for a frequency. */
#define EX_NA ((double)NAN)
#define EX_NO_FREQ (-1L)

/* The larger N, as a multiple of N, at which an N -> infinity form's limit
 * check compares it with the exact value (ex_row.limit_gap). */
#define EX_LARGE_N_FACTOR 16u

/* A complex value by its parts (EX_NA where unknown). */
typedef struct {
    double re, im;
} ex_complex;

typedef struct {
    const char *section;  /* "sec1" ... */
    const char *quantity; /* short name, no commas */
    const char *equation; /* "eq. 23" or "23"; no commas */
    const char *pattern;  /* pattern kind name, or "" */
    long freq, freq2;     /* frequency indices or EX_NO_FREQ */
    double closed_form;   /* the note's closed form (the bound, for ex_row_print_bound), or EX_NA */
    double exact;         /* exact discrete prediction, or EX_NA */
    double measured;      /* measured value, or EX_NA */
    double stderr_;       /* its standard error (0 for a deterministic value) */
    double limit_gap;     /* for an N -> infinity form: its relative gap to the exact
                             value at a larger N; EX_NA otherwise */
    double abs_floor;     /* scale below which a difference counts as zero (e.g. 1e-12 K/N);
                             0 means 1e-300 */
} ex_row;

/* A row from its fields in ex_row's order, with no limit check (limit_gap EX_NA). */
ex_row ex_row_of(const char *section, const char *quantity, const char *equation,
                 const char *pattern, long freq, long freq2, double closed_form, double exact,
                 double measured, double stderr_, double abs_floor);

/* Relative gap below which a closed form counts as equal to the exact value. */
#define EX_EXACT_RTOL 1e-9
/* |z| above which a measurement refutes a prediction. */
#define EX_Z_REJECT 5.0

/* (measured - predicted) / max(stderr, abs_floor): a deterministic value
 * (stderr 0) that agrees to rounding gets z = 0, not 0/0. EX_NA if any input
 * is missing. abs_floor <= 0 means 1e-300. */
double ex_z(double measured, double predicted, double stderr_, double abs_floor);

/* The larger |z| (ex_z) of the real and the imaginary part. */
double ex_z_complex(ex_complex measured, ex_complex predicted, ex_complex stderr_,
                    double abs_floor);

/* Relative gap |closed - exact| / max(|closed|, |exact|, abs_floor); 0 when
 * |closed - exact| <= abs_floor (below the rounding scale). */
double ex_rel_gap(double closed_form, double exact, double abs_floor);

/* The verdict rule for a value (printed by --help in ex_verdict_rules):
 *   holds  : rel_gap(closed, exact) <= EX_EXACT_RTOL;
 *   limit  : not holds, the closed form is an N -> infinity form, and its gap
 *            to the exact value at a larger N (gap_larger_n, computed by the
 *            caller from exact values) is below half the gap at this N;
 *   fails  : not holds, not limit, and the measurement refutes the closed form
 *            (|z_closed| > EX_Z_REJECT) while agreeing with the exact value
 *            (|z_exact| <= EX_Z_REJECT);
 *   approx : otherwise: the closed form is not exact, but the measurement does
 *            not separate it from the exact value (the gap column gives the size).
 * gap_larger_n: EX_NA if the form is not a limit form. abs_floor: the scale
 * below which a difference counts as zero (e.g. K/N * 1e-12). */
const char *ex_verdict(double closed_form, double exact, double measured, double stderr_,
                       double gap_larger_n, double abs_floor);

/* The verdict rule for an upper bound on a quantity whose exact value is known:
 *   holds  : exact <= bound (to EX_EXACT_RTOL relative): the bound is valid here;
 *   fails  : exact > bound, and the measurement exceeds the bound
 *            (z_closed > EX_Z_REJECT) while agreeing with the exact value;
 *   approx : otherwise (violated by less than the measurement resolves). */
const char *ex_verdict_bound(double bound, double exact, double measured, double stderr_,
                             double abs_floor);

/* Starts output: the CSV header, or a title and the table header. */
void ex_begin(const ex_options *opt, const char *title);
/* One row, in the chosen format; the verdict is computed by ex_verdict from
 * the row's numbers (empty when closed_form or exact is EX_NA). The verdict
 * is also returned ("" if none). */
const char *ex_row_print(const ex_options *opt, const ex_row *row);
/* The same for a row whose closed_form is an upper bound on the quantity
 * (the note's inequalities): the verdict is ex_verdict_bound's, and table
 * mode marks it "bound". */
const char *ex_row_print_bound(const ex_options *opt, const ex_row *row);
/* The two rows of a complex quantity, "Re <quantity>" then "Im <quantity>",
 * each printed by ex_row_print from the matching parts of closed_form, exact,
 * measured and stderr_ (the other fields as in ex_row_of). */
void ex_row_print_complex(const ex_options *opt, const char *section, const char *quantity,
                          const char *equation, const char *pattern, long freq, long freq2,
                          ex_complex closed_form, ex_complex exact, ex_complex measured,
                          ex_complex stderr_, double abs_floor);
/* A sub-heading in table mode (ignored in CSV mode). */
void ex_heading(const ex_options *opt, const char *text);
/* A free-text line in table mode (ignored in CSV mode). */
void ex_note(const ex_options *opt, const char *text);
/* The same with printf formatting. */
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
void ex_notef(const ex_options *opt, const char *fmt, ...);
/* Ends output: in table mode, a line counting the rows whose measurement
 * disagrees with the exact prediction (|z_exact| > EX_Z_REJECT), if any.
 * Returns that count. */
unsigned ex_end(const ex_options *opt);

#endif /* MCSPEC_EXAMPLE_REPORT_H */
