/* The bilinear, clamp-to-edge lookup of a square table at texel centres,
 * as text for the shaders: luts/table_lookup.inc (its header comment says
 * what it computes and which dialect it expects), the one source of the
 * lookup C compiles through luts/table_lookup_c.h. A shader writer writes
 * its table as arrays, its dialect's definitions, then this text (the DFG
 * and LTC tables' writers do). */
#ifndef GTLAB_LUTS_TABLE_LOOKUP_H
#define GTLAB_LUTS_TABLE_LOOKUP_H

/* The text of luts/table_lookup.inc, byte for byte, embedded by the build
 * (gtlab_embed_text, cmake/gtlab_embed.cmake). */
extern const char table_lookup_inc_text[];

#endif
