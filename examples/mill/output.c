/* output.c: the picture the mill example draws with cairo for --ore, the
 * feed's and product's size distributions; the charge and power pictures are
 * the shared drum pictures (examples/common/drum_plot.c), its VTK files come
 * from the library (demill/vtk.h). */
#include <math.h>

#include <cairo.h>

#include "mill.h"
#include "plot.h"

int draw_product(const char *path, const ore_result *r, const char *title)
{
    const int wd = 1000, ht = 560, l = 80, r_ = 30, tp = 60, bt = 60;
    /* the log size axis over the classes' limits but the sink's 0 */
    const double lx0 = log10(r->limits[r->n - 1]), lx1 = log10(r->limits[0]);
    cairo_surface_t *s;
    cairo_t *cr = plot_canvas(wd, ht, 13, &s);
    const plot_area a = {l, tp, wd - l - r_, ht - tp - bt, lx0, lx1, 0, 100};
    char label[96];
    /* decades and 2, 5 within them, in mm */
    for (double dec = floor(lx0); dec <= lx1; dec += 1)
        for (int m = 1; m <= 5; m += m == 1 ? 1 : 3) {
            const double lx = dec + log10(m);
            if (lx < lx0 - 1e-9 || lx > lx1 + 1e-9)
                continue;
            snprintf(label, sizeof label, "%g", 1e3 * pow(10, lx));
            plot_grid(cr, plot_px(&a, lx), tp, plot_px(&a, lx), ht - bt, plot_px(&a, lx) - 8,
                      ht - bt + 18, label);
        }
    for (int pk = 0; pk <= 100; pk += 20) {
        snprintf(label, sizeof label, "%d", pk);
        plot_grid(cr, l, plot_py(&a, pk), wd - r_, plot_py(&a, pk), l - 35, plot_py(&a, pk) + 4,
                  label);
    }
    /* the curves through (upper limit, passing) of every class but the sink */
    const double colour[2][3] = {{0.45, 0.45, 0.45}, {0.13, 0.37, 0.66}};
    for (int c = 0; c < 2; c++) {
        const double *p = c ? r->product_passing : r->feed_passing;
        cairo_set_source_rgb(cr, colour[c][0], colour[c][1], colour[c][2]);
        cairo_set_line_width(cr, 2.2);
        for (uint32_t k = 0; k < r->n; k++) {
            const double x = plot_px(&a, log10(r->limits[k])), y = plot_py(&a, 100 * p[k]);
            if (k == 0)
                cairo_move_to(cr, x, y);
            else
                cairo_line_to(cr, x, y);
        }
        cairo_stroke(cr);
        cairo_move_to(cr, l + 20, tp + 22 + 20 * c);
        snprintf(label, sizeof label, c ? "product: P80 %.3g mm" : "feed: F80 %.3g mm",
                 1e3 * (c ? r->p80 : r->f80));
        cairo_show_text(cr, label);
    }
    plot_frame(cr, l, tp, wd - l - r_, ht - tp - bt, ht, wd / 2 - 40, "size [mm], log scale");
    cairo_move_to(cr, l, 25);
    cairo_show_text(cr, title);
    cairo_move_to(cr, l, 47);
    cairo_show_text(cr, "cumulative mass passing [%]");
    cairo_destroy(cr);
    return plot_save_png(s, path, "mill");
}
