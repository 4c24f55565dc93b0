/* The figure of mcspec integrate: mean squared error against K on log-log
 * axes, per family, with its least-squares line and the exact MSE. */
#include "integrate.h"
#include "plot.h"

#include <math.h>
#include <stdio.h>

static int write_figure(FILE *fp, const char *tmp, const void *ctx)
{
    const integ_ctx *c = ctx;
    FILE *d = cli_plot_data(tmp, "data.txt");
    if (d == NULL)
        return -1;
    int blocks = 0;
    for (int f = 0; f < CLI_INTEG_FAMILIES; ++f) {
        if (!c->fam_on[f])
            continue;
        for (size_t i = 0; i < c->ng; ++i) {
            const group *g = &c->g[i];
            fprintf(d, "%zu", g->k);
            cli_plot_value(d, g->mse[f]);
            cli_plot_value(d, isnan(g->se[f]) ? 0.0 : g->se[f]);
            cli_plot_value(d, g->exact[f]);
            fputc('\n', d);
        }
        fputs("\n\n", d);
        ++blocks;
    }
    if (fclose(d) != 0)
        return -1;
    fprintf(fp, "set title \"mcspec integrate: %s (%zuD), mean squared error against K\\n"
            "points: measured ± 1 standard error; dashed: least-squares fit%s\" noenhanced\n",
            c->o->kind != NULL ? c->o->kind : "point files", c->dim,
            c->ref != MCS_INTEGRATE_NONE ? "; solid: exact" : "");
    fputs("set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\n"
          "set xlabel \"points per set K\"\nset ylabel \"mean squared error\"\n", fp);
    cli_plot_style(fp);
    fputs("set key top right box opaque samplen 2\n", fp);
    const size_t k0 = c->g[0].k, k1 = c->g[c->ng - 1u].k;
    fprintf(fp, "set xrange [%.17g:%.17g]\n", (double)k0 / 1.5, (double)k1 * 1.5);
    fputs("plot ", fp);
    int b = 0;
    for (int f = 0; f < CLI_INTEG_FAMILIES; ++f) {
        if (!c->fam_on[f])
            continue;
        /* the fitted line through the rows' centre of mass in log-log */
        double n = 0, sx = 0, sy = 0;
        for (size_t i = 0; i < c->ng; ++i)
            if (c->g[i].mse[f] > 0.0) {
                n += 1.0;
                sx += log((double)c->g[i].k);
                sy += log(c->g[i].mse[f]);
            }
        const char *name = mcs_integrand_family_str((mcs_integrand_family)f);
        fprintf(fp, "%s", b > 0 ? ", \\\n     " : "");
        cli_plot_data_ref(fp, tmp, "data.txt");
        char label[64];
        if (isnan(c->slope[f]))
            snprintf(label, sizeof label, "%s", name);
        else
            snprintf(label, sizeof label, "%s (slope %.2f)", name, c->slope[f]);
        fprintf(fp, " index %d using 1:2:3 with yerrorbars lc %d pt 7 ps 0.8 title \"%s\" noenhanced",
                b, b + 1, label);
        if (c->ref != MCS_INTEGRATE_NONE) {
            fputs(", ", fp);
            cli_plot_data_ref(fp, tmp, "data.txt");
            fprintf(fp, " index %d using 1:4 with lines lc %d lw 1.5 notitle", b, b + 1);
        }
        if (!isnan(c->slope[f]) && n > 0.0)
            fprintf(fp, ", exp(%.17g + %.17g * (log(x) - %.17g)) with lines lc %d dt 2 notitle",
                    sy / n, c->slope[f], sx / n, b + 1);
        ++b;
    }
    fputc('\n', fp);
    return blocks > 0 ? 0 : -1;
}

int cli_integrate_plot(const char *cmd, const char *path, const integ_ctx *c)
{
    return cli_plot_render(cmd, path, write_figure, c);
}
