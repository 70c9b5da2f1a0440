/* Unit normals in a G-buffer: the encodings a deferred renderer chooses
 * between, each an encode (what the G-buffer pass writes, with the target's
 * rounding) and a decode (what the lighting pass reads).
 *
 * RGB8 (Kaplanyan 2010): the code c = round((x * 0.5 + 0.5) * 255) per
 * component of a vector x along n; decode normalize(2 c / 255 - 1).
 *   naive      x = n (the normalised normal)
 *   max        x = n / max|n_i| (on the cube's surface)
 *   best fit   x = n / max|n_i| * t, t from the best-fit table
 *              (best_fit_normals/best_fit_normals.h), point or bilinear lookup
 * Octahedral (Meyer et al. 2010; Cigolle et al. 2014, "A Survey of
 * Efficient Representations for Independent Unit Vectors", JCGT 3(2)):
 * n / (|x| + |y| + |z|) on the octahedron, the lower half folded over the
 * diagonals, two signed-normalised integers of b bits each,
 * code = round(clamp(p, -1, 1) (2^(b-1) - 1)). The precise encode
 * (Cigolle et al. §3.2, "oct*P") tries the four codes about p (floor and
 * ceil per axis) and keeps the one that decodes closest to n. */
#ifndef GTLAB_BEST_FIT_NORMALS_NORMAL_ENCODING_H
#define GTLAB_BEST_FIT_NORMALS_NORMAL_ENCODING_H

typedef enum { RGB8_NAIVE, RGB8_MAX, RGB8_BEST_FIT_POINT, RGB8_BEST_FIT_BILINEAR, RGB8_ENCODING_COUNT } rgb8_encoding;

/* The best-fit table the BEST_FIT encodings read (best_fit_normals/best_fit_normals.h). */
typedef struct {
    const float *table;
    int size;
} best_fit_table;

const char *rgb8_encoding_name(int encoding);

/* Writes the three 8-bit codes of unit n; `table` is read by the best-fit
 * encodings only (may be NULL for the others). */
void rgb8_encode(rgb8_encoding encoding, const best_fit_table *table, const double n[3], int code[3]);
void rgb8_decode(const int code[3], double n[3]);

/* Octahedral at `bits` per axis (2..16), plain or precise. */
void octahedral_encode(const double n[3], int bits, int precise, int code[2]);
void octahedral_decode(const int code[2], int bits, double n[3]);

#endif
