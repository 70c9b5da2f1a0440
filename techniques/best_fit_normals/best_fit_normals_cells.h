/* Counting the RGB8 cells a normal encoding uses: the audit of the talk's
 * "Storage techniques breakdown" (Kaplanyan 2010): "normalized normals
 * ~289880 cells out of 16777216, ~1.73 %; divided by maximum component
 * ~390152, ~2.33 %; best fit ~16482364, ~98.2 %". Each count below states
 * exactly what it counts; a cell is one of the 256^3 codes, its value
 * (2 c / 255 - 1) per component, its box the values that round to it.
 *
 *   exact counts, by enumerating the 256^3 cells:
 *     sphere     cells whose box the unit sphere crosses: every one is the
 *                code of some unit vector, so this is what naive storage can
 *                reach (min |x| <= 1 <= max |x| over the box)
 *     surface    cells on the cube's surface (a code 0 or 255): what
 *                division by the maximum component reaches, 256^3 - 254^3
 *     distinct   cells whose value is not a multiple of another cell's
 *                value (gcd of the odd integers 2c - 255 is 1): the number
 *                of distinct directions 24 bits can encode at all
 *   sampled counts: the distinct cells an encoding writes for the texel
 *   centres of a cubemap of `face` x `face` texels per face, the talk's
 *   way of baking directions ("bake it into a cubemap"): such counts grow
 *   with the face size towards the exact ones. */
#ifndef GTLAB_BEST_FIT_NORMALS_CELLS_H
#define GTLAB_BEST_FIT_NORMALS_CELLS_H

enum { BFN_CELL_COUNT = 256 * 256 * 256 };

long bfn_cells_sphere(void);
long bfn_cells_surface(void);
long bfn_cells_distinct(int threads);

typedef enum { BFN_SAMPLED_NAIVE, BFN_SAMPLED_MAX, BFN_SAMPLED_BEST_FIT } bfn_sampled_encoding;

/* Distinct cells written for the 6 face^2 cubemap texel directions (face
 * even); the best-fit encoding runs the talk's search (published metric)
 * per texel. -1 if out of memory. The count does not depend on threads.
 * bfn_cells_sampled visits 1/48 of the texels and adds the 48 symmetric
 * images of each cell; _direct visits every texel (the test's check that
 * the encodings commute with the cube's symmetries). */
long bfn_cells_sampled(bfn_sampled_encoding encoding, int face, int threads);
long bfn_cells_sampled_direct(bfn_sampled_encoding encoding, int face, int threads);

#endif
