/* The arena of one adversarial row (private to adv_*.c). */
#ifndef ADV_WORLD_H
#define ADV_WORLD_H

#include "adv.h"

#define ADV_ARENA_BYTES (6u << 20)
#define ADV_GUARD 64u
#define ADV_GUARD_BYTE 0xA5
#define ADV_FILL_BYTE 0x5A /* outputs start as 0x5A5A...: a finite double, never a result */
#define ADV_MAX_REGIONS 32

typedef struct {
    size_t off, bytes; /* payload; guards before and after */
    int slot;          /* -1 for an object's dependency (the importance behind a pattern) */
    int kind;          /* slot kind; dependencies count as const objects */
} adv_region;

extern unsigned char adv_arena[ADV_ARENA_BYTES];
extern unsigned char adv_snap[ADV_ARENA_BYTES];
extern size_t adv_used;
extern adv_region adv_regs[ADV_MAX_REGIONS];
extern int adv_nregs;
extern int adv_overflow;

void adv_world_reset(void);
void *adv_region_for(size_t bytes, int slot, int kind);
double adv_scalar_double(const adv_row *r, int i);
void adv_fill_array(const adv_row *r, int i, void *p, size_t len, size_t n_bins);

#endif /* ADV_WORLD_H */
