/* The figure of a 2D point-set spectrum (see plot.h): the image of the mean
 * periodogram and its radial profile, side by side. The image is tone-mapped
 * as papers show blue noise: a log colour scale over the 30 dB below the
 * largest <P> at k != 0 (lower values drawn at its floor), the DC term
 * masked (P(0) = K would flatten any scale). */
#include "plot.h"

#include <math.h>
#include <stdio.h>

typedef struct {
    const cli_plot_info *info;
    const cli_ps_row *rows2d, *radial;
    size_t nrows2d, nradial;
} pointset2d_figure;

/* The colour scale's span below its top: 30 dB. */
#define IMAGE_SPAN 1e-3

/* Largest <P> drawn in the image, k != 0 (P(0) = K would flatten the colour
 * scale); 1 if nothing is positive. */
static double image_top(const pointset2d_figure *fig)
{
    double top = 0.0;
    for (size_t i = 0; i < fig->nrows2d; ++i) {
        const cli_ps_row *r = &fig->rows2d[i];
        if ((r->kx != 0 || r->ky != 0) && !isnan(r->power) && r->power > top)
            top = r->power;
    }
    return top > 0.0 ? top : 1.0;
}

/* cli_plot_row_fn of the radial rows: no closed form. */
static void radial_values(const void *rows, size_t i, double v[4])
{
    const cli_ps_row *r = (const cli_ps_row *)rows + i;
    v[0] = r->power;
    v[1] = r->power_stderr;
    v[2] = r->exact;
    v[3] = (double)NAN;
}

static int has_exact(const pointset2d_figure *fig)
{
    for (size_t i = 1; i < fig->nradial; ++i)
        if (!isnan(fig->radial[i].exact))
            return 1;
    return 0;
}

/* data.txt: the profile, r >= 1, in cli_plot_profile's columns; data2.txt:
 * the image, one scan line per ky (gnuplot's grid format). */
static int write_data(const char *tmp, const pointset2d_figure *fig, const cli_plot_axis *axis)
{
    FILE *fp = cli_plot_data(tmp, "data.txt");
    if (fp == NULL)
        return -1;
    fputs("# r radial radial-stderr radial+stderr exact closed\n", fp);
    for (size_t i = 1; i < fig->nradial; ++i) {
        const cli_ps_row *r = &fig->radial[i];
        cli_plot_profile_row(fp, axis, r->kx, r->power, r->power_stderr, r->exact, (double)NAN);
    }
    int ok = fclose(fp) == 0;
    fp = cli_plot_data(tmp, "data2.txt");
    if (fp == NULL)
        return -1;
    fputs("# kx ky power (tone-mapped: at least the scale's floor; DC masked)\n", fp);
    const double floor_ = IMAGE_SPAN * image_top(fig);
    for (size_t i = 0; i < fig->nrows2d; ++i) {
        const cli_ps_row *r = &fig->rows2d[i];
        if (i > 0u && r->ky != fig->rows2d[i - 1u].ky)
            fputc('\n', fp);
        fprintf(fp, "%ld %ld", r->kx, r->ky);
        const int dc = r->kx == 0 && r->ky == 0;
        cli_plot_value(fp, dc ? (double)NAN : fmax(r->power, floor_));
        fputc('\n', fp);
    }
    return fclose(fp) == 0 && ok ? 0 : -1;
}

static void write_image_panel(FILE *fp, const char *tmp, const pointset2d_figure *fig)
{
    const long f = fig->rows2d[fig->nrows2d - 1u].kx;
    fputs("set title \"mean periodogram ⟨P(k)⟩, log scale, k = 0 masked\" noenhanced\n"
          "set xlabel \"k_x\"\nset ylabel \"k_y\"\n"
          "set cblabel \"⟨P(k)⟩ (30 dB below the largest k ≠ 0)\" noenhanced\n"
          "set logscale cb\nset format cb \"%g\"\nset object 1 rectangle from graph 0,0 "
          "to graph 1,1 behind fillcolor rgb '#808080' fillstyle solid noborder\n"
          "set size ratio -1\nset border lw 1.2\nunset key\n"
          "set palette defined (0 '#000004', 1 '#3b0f70', 2 '#8c2981', 3 '#de4968', "
          "4 '#fe9f6d', 5 '#fcfdbf')\n", fp);
    const double top = image_top(fig);
    fprintf(fp, "set xrange [%.1f:%.1f]\nset yrange [%.1f:%.1f]\nset cbrange [%.17g:%.17g]\n",
            -(double)f - 0.5, (double)f + 0.5, -(double)f - 0.5, (double)f + 0.5,
            IMAGE_SPAN * top, top);
    fputs("plot ", fp);
    cli_plot_data_ref(fp, tmp, "data2.txt");
    fputs(" using 1:2:3 with image notitle\n", fp);
    fputs("unset object 1\nunset logscale cb\n", fp);
}

static void write_profile_panel(FILE *fp, const char *tmp, const pointset2d_figure *fig,
                                const cli_plot_axis *axis)
{
    const long f = fig->radial[fig->nradial - 1u].kx;
    const long w = fig->nradial > 1u ? fig->radial[1].kx : 1;
    fprintf(fp, "set title \"radial average over the annuli r ≤ |k| < r + %ld\" noenhanced\n", w);
    fputs("set xlabel \"radius r\"\nset ylabel \"radial average of ⟨P(k)⟩\"\n"
    "set size noratio\nunset cblabel\nunset colorbox\n", fp);
    cli_plot_style(fp);
    fprintf(fp, "set xrange [0.5:%.17g]\n", (double)f + 0.5);
    cli_plot_axis_write(fp, axis);
    const cli_plot_series s = {tmp, "data.txt", "measured",
                               has_exact(fig) ? fig->info->exact_label : NULL, NULL};
    cli_plot_profile(fp, &s);
}

static int write_pointset2d(FILE *fp, const char *tmp, const void *ctx)
{
    const pointset2d_figure *fig = ctx;
    /* r >= 1 (r = 0 is P(0) = K); the image keeps its linear colour scale. */
    cli_plot_axis axis;
    cli_plot_axis_init(&axis, fig->info->log_y, fig->radial, 1u, fig->nradial, radial_values);
    if (write_data(tmp, fig, &axis) != 0)
        return -1;
    fputs("set multiplot layout 1,2 title ", fp);
    cli_plot_title(fp, fig->info);
    fputc('\n', fp);
    write_image_panel(fp, tmp, fig);
    write_profile_panel(fp, tmp, fig, &axis);
    fputs("unset multiplot\n", fp);
    return 0;
}

int cli_plot_pointset2d(const char *cmd, const char *path, const cli_plot_info *info,
                        const cli_ps_row *rows2d, size_t nrows2d, const cli_ps_row *radial,
                        size_t nradial)
{
    const pointset2d_figure fig = {info, rows2d, radial, nrows2d, nradial};
    return cli_plot_render(cmd, path, write_pointset2d, &fig);
}
