/* Option parsing, one-line messages and number formats shared by every
 * mcspec subcommand. */
#include "cli.h"

#include "mcspec/pattern.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void vreport(const char *cmd, const char *fmt, va_list ap)
{
    /* One line: anything after a newline in the message would break the
     * "one line on stderr" promise, so the message is formatted first. */
    char msg[1024];
    vsnprintf(msg, sizeof msg, fmt, ap);
    for (char *c = msg; *c != '\0'; ++c)
        if (*c == '\n' || *c == '\r')
            *c = ' ';
    fprintf(stderr, "%s: %s\n", cmd, msg);
}

int cli_fail(const char *cmd, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vreport(cmd, fmt, ap);
    va_end(ap);
    return CLI_EXIT_USAGE;
}

int cli_internal(const char *cmd, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vreport(cmd, fmt, ap);
    va_end(ap);
    return CLI_EXIT_FAIL;
}

void *cli_alloc(const char *cmd, size_t count, size_t size)
{
    if (count == 0u)
        count = 1u;
    if (size == 0u)
        size = 1u;
    if (count > (size_t)-1 / size) {
        cli_internal(cmd, "out of memory (%zu x %zu bytes)", count, size);
        return NULL;
    }
    void *p = calloc(count, size);
    if (p == NULL)
        cli_internal(cmd, "out of memory (%zu x %zu bytes)", count, size);
    return p;
}

int cli_grow(const char *cmd, void **buf, size_t *bytes, size_t need, size_t k)
{
    if (need <= *bytes)
        return 0;
    void *w = realloc(*buf, need);
    if (w == NULL)
        return cli_internal(cmd, "out of memory for a set of %zu points", k);
    *buf = w;
    *bytes = need;
    return 0;
}

int cli_parse_u64(const char *text, uint64_t min, uint64_t max, uint64_t *out)
{
    /* strtoull alone would accept "-1", " 7" and "7junk"; digits only. */
    if (text == NULL || *text == '\0')
        return -1;
    for (const char *c = text; *c != '\0'; ++c)
        if (*c < '0' || *c > '9')
            return -1;
    errno = 0;
    unsigned long long v = strtoull(text, NULL, 10);
    if (errno == ERANGE || v < min || v > max)
        return -1;
    *out = (uint64_t)v;
    return 0;
}

/* cli_fail for the parser: the message, then CLI_BAD. */
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static int bad(const char *cmd, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vreport(cmd, fmt, ap);
    va_end(ap);
    return CLI_BAD;
}

static cli_opt *find_opt(cli_parser *p, const char *name, size_t len)
{
    for (size_t i = 0; i < p->nopts; ++i)
        if (strlen(p->opts[i].name) == len && strncmp(p->opts[i].name, name, len) == 0)
            return &p->opts[i];
    return NULL;
}

static int set_opt(cli_parser *p, cli_opt *o, const char *value)
{
    uint64_t v = 0;
    switch (o->type) {
    case CLI_OPT_FLAG:
        *(int *)o->value = 1;
        return CLI_PARSED;
    case CLI_OPT_STRING:
        if (*value == '\0')
            return bad(p->cmd, "--%s needs a value", o->name);
        *(const char **)o->value = value;
        return CLI_PARSED;
    case CLI_OPT_SIZE:
    case CLI_OPT_U64:
        if (cli_parse_u64(value, o->min, o->max, &v) != 0)
            return bad(p->cmd, "--%s expects a whole number from %llu to %llu, not '%s'",
                       o->name, (unsigned long long)o->min, (unsigned long long)o->max, value);
        if (o->type == CLI_OPT_SIZE)
            *(size_t *)o->value = (size_t)v;
        else
            *(uint64_t *)o->value = v;
        return CLI_PARSED;
    }
    return CLI_BAD;
}

/* One "--name[=value]" at argv[*i]; takes the next argument as the value
 * when the option needs one and has no "=". */
static int parse_long(cli_parser *p, int argc, char **argv, int *i)
{
    const char *arg = argv[*i] + 2;
    const char *eq = strchr(arg, '=');
    size_t len = eq != NULL ? (size_t)(eq - arg) : strlen(arg);
    cli_opt *o = find_opt(p, arg, len);
    if (o == NULL)
        return bad(p->cmd, "unknown option '--%.*s' (see %s --help)", (int)len, arg, p->cmd);
    const char *value = NULL;
    if (o->type == CLI_OPT_FLAG) {
        if (eq != NULL)
            return bad(p->cmd, "--%s takes no value", o->name);
    } else if (eq != NULL) {
        value = eq + 1;
    } else if (*i + 1 < argc) {
        value = argv[++*i];
    } else {
        return bad(p->cmd, "--%s needs a value", o->name);
    }
    if (o->given && o->type != CLI_OPT_FLAG)
        return bad(p->cmd, "--%s given twice", o->name);
    o->given = 1;
    return set_opt(p, o, value);
}

int cli_parse(cli_parser *p, int argc, char **argv)
{
    int options_done = 0;
    p->nargs = 0;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (!options_done && (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0)) {
            fputs(p->help, stdout);
            if (p->help_more != NULL)
                fputs(p->help_more, stdout);
            return CLI_HELP;
        }
        if (!options_done && strcmp(a, "--") == 0) {
            options_done = 1;
        } else if (!options_done && a[0] == '-' && a[1] == '-') {
            int rc = parse_long(p, argc, argv, &i);
            if (rc != CLI_PARSED)
                return rc;
        } else if (!options_done && a[0] == '-' && a[1] != '\0') {
            return bad(p->cmd, "unknown option '%s' (options are spelled --name; see %s --help)",
                       a, p->cmd);
        } else if (p->nargs < p->max_args) {
            p->args[p->nargs++] = a;
        } else {
            return bad(p->cmd, "unexpected argument '%s' (see %s --help)", a, p->cmd);
        }
    }
    return CLI_PARSED;
}

void cli_csv_double(char *buf, size_t size, double x)
{
    if (isnan(x))
        buf[0] = '\0';
    else
        snprintf(buf, size, "%.17g", x);
}

void cli_table_double(char *buf, size_t size, int width, double x)
{
    if (isnan(x))
        snprintf(buf, size, "%*s", width, "-");
    else
        snprintf(buf, size, "%*.6g", width, x);
}

double cli_z(double measured, double predicted, double stderr_, double floor)
{
    if (isnan(measured) || isnan(predicted) || isnan(stderr_))
        return (double)NAN;
    double d = measured - predicted;
    if (fabs(d) <= floor)
        return 0.0;
    return d / fmax(stderr_, floor);
}

int cli_parse_one(const char *cmd, const char *help, const char *help_more, cli_opt *opts,
                  size_t nopts, int argc, char **argv, const char **arg)
{
    const char *args[1] = {NULL};
    cli_parser p = {cmd, help, opts, nopts, args, 1u, 0u, help_more};
    int rc = cli_parse(&p, argc, argv);
    *arg = args[0];
    return rc;
}

int cli_pattern_kind(const char *text)
{
    for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i)
        if (strcmp(text, mcs_pattern_kind_str((mcs_pattern_kind)i)) == 0)
            return i;
    return -1;
}
