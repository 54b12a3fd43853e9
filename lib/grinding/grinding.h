/* grinding.h: the grinding module (lib/grinding/): a grinding object, the
 * ore breakage models (breakage.c) and the batch-grinding population
 * balance (balance.c), behind the API of include/demill/grinding.h
 * (grinding.c). It uses only the base layer. */
#ifndef DM_GRINDING_H
#define DM_GRINDING_H

#include "base/base.h"

#define DM_GRINDING_MAGIC 0x6772696e64u /* "grind" */
#define DM_GRINDING_MAX_CLASSES 200u
#define DM_TFAMILY_MAX_ROWS 100u
#define DM_TFAMILY_COLUMNS 6 /* t10, t2, t4, t25, t50, t75 */

enum { DM_ORE_NONE = 0, DM_ORE_JK = 1, DM_ORE_TAVARES = 2 };

/* An ore's breakage model: the JKMRC drop-weight model (a, b) or Tavares
 * and King's (e_inf ... gamma, with a and b as A' and b'), and the
 * t-family table both use. */
typedef struct dm_ore {
    int model;
    double a, b;
    double e_inf, d0, phi, sigma, emax_ratio, gamma;
    size_t rows;
    double *table; /* rows × DM_TFAMILY_COLUMNS, % */
} dm_ore;

/* A grinding object; its dm_base first, so that dm_fail() writes its
 * message as it does a world's. */
struct demill_grinding {
    dm_base base;
    uint32_t n;   /* size classes, the last the sink */
    double top;   /* upper limit of class 0, m */
    double *mass; /* the product's mass per class (the feed's until run) */
    double *s;    /* specific breakage rates, 1/s */
    double *b;    /* appearance function, b[i * n + j] */
    double total; /* the feed's mass, 0 before a feed is set */
    double time;  /* grinding time since the feed was set, s */
    double damage_time; /* the time of the damage sequences of the rates, s; 0: single impacts */
    dm_ore ore;
};

/* The upper limit of class i (i < n), m. */
double dm_class_limit(const demill_grinding *g, uint32_t i);

/* breakage.c */
/* Checks a t-family table; 0, or writes a message to `why` (size len). */
int dm_tfamily_check(size_t rows, const double *table, char *why, size_t len);
/* t2, t4, t25, t50, t75 at t10 (0 < t10 <= the last row's), into tn[5]. */
void dm_tfamily_at(const dm_ore *ore, double t10, double *tn);
/* The model's t10, %, for a parent of size d broken by specific energy e. */
double dm_ore_t10(const dm_ore *ore, double d, double e);
/* Tavares and King: the median fracture energy E50 of size d, J/kg. */
double dm_tk_e50(const dm_ore *ore, double d);
/* Tavares and King: the fraction of particles of size d broken within
 * `impacts` impacts of specific energy e each. */
double dm_tk_broken(const dm_ore *ore, double d, double e, uint32_t impacts);
/* The same, into *broken, and into *survived the mean number of those
 * impacts a particle survives to receive: sum_{m<impacts} (1 - F_m), F_m the
 * fraction broken within m impacts (F_0 = 0). */
void dm_tk_sequence(const dm_ore *ore, double d, double e, uint32_t impacts, double *broken,
                    double *survived);
/* The appearance column of parent class j (< n - 1) at t10 (in the table's
 * range): col[i] for i = 0 .. n - 1. */
void dm_appearance_column(const demill_grinding *g, uint32_t j, double t10, double *col);

/* balance.c */
/* mass <- exp(A t) mass for the lower triangular A of the batch grinding
 * equation; 0, or DEMILL_ERR_OUT_OF_MEMORY (mass untouched). */
demill_status dm_balance_advance(const demill_grinding *g, double t, double *mass);
/* The fraction of the product finer than size x (x >= the sink's limit). */
double dm_balance_passing(const demill_grinding *g, double x);
/* The size that a fraction f passes; -1 when it lies in the sink. */
double dm_balance_size(const demill_grinding *g, double f);

#endif /* DM_GRINDING_H */
