/* The orders of the GTAO talk's 16 spatial directions over a 4x4 tile
 * (seeds/001, "Noise Distribution"): the talk's rows, each row holding a
 * full rotation (one direction in each quarter of the half-turn, so a filter
 * that averages a single row of the 4x4 kernel still sees every direction),
 * and the Morton order it says they "worked better than": direction k/16 at
 * the k-th cell of the Z-order curve of the tile, so each 2x2 quad holds
 * four neighbouring directions of one quarter.
 *
 * gtao_params.pattern selects the order: 0 regular slices (no pattern),
 * GTAO_PATTERN_ROWS (1, the talk's), GTAO_PATTERN_MORTON. The temporal
 * rotations and offsets are the same for both orders (below). */
#ifndef GTLAB_GTAO_GTAO_PATTERN_H
#define GTLAB_GTAO_GTAO_PATTERN_H

enum { GTAO_PATTERN_OFF = 0, GTAO_PATTERN_ROWS = 1, GTAO_PATTERN_MORTON = 2 };

/* The Morton index of (x & 3, y & 3): bits x0 y0 x1 y1 from the lowest. */
int gtao_morton_index(int x, int y);
/* Direction of pixel (x, y) in Morton order, as a fraction of a turn: morton / 16. */
float gtao_spatial_direction_morton(int x, int y);
/* The spatial direction of `pattern` (GTAO_PATTERN_ROWS or _MORTON) at (x, y). */
float gtao_pattern_direction(int x, int y, int pattern);

/* The spatio-temporal pattern of the talk, as fractions of a turn in [0, 1).
 * Spatial: 16 directions over each 4x4 tile, every row holding one direction
 * in each quarter of the half-turn; 4 step offsets per tile. Temporal: 6
 * rotations and 4 offsets. */
float gtao_spatial_direction(int x, int y);
float gtao_spatial_direction_as_transcribed(int x, int y);
float gtao_spatial_offset(int x, int y);
float gtao_temporal_rotation(int frame);
float gtao_temporal_offset(int frame);

#endif
