/* The height field a depth buffer stands for, shared by the height-field AO
 * reference (techniques/ao/heightfield_ao_integrator.c) and the screen-space
 * techniques (realtime/screen_space.c), two independent implementations that
 * must agree on what the depth buffer means:
 *  - each pixel is a planar piece: along an eye ray through any point of the
 *    pixel, the surface lies where the ray meets the tangent plane of the
 *    surface seen at the pixel's centre (its position and normal);
 *  - that depth is clamped to the range of the centre depths of the pixel and
 *    its covered 8 neighbours (a missing neighbour mirrored from the opposite
 *    one, 2 d - d_opposite, so image borders and silhouettes keep a range): a plane seen at a grazing angle (a wall seen
 *    from above) would otherwise put phantom surface far above or below the
 *    pixel, while on a smooth surface the depth across a pixel lies between
 *    its neighbours' anyway (a plane stays exact); a plane seen edge-on
 *    (|n . w| < MIN_FACING for the unit eye ray w) takes the centre's depth;
 *  - everything behind the surface is solid (infinite thickness). */
#ifndef GTLAB_CORE_OPTICS_HEIGHTFIELD_MODEL_H
#define GTLAB_CORE_OPTICS_HEIGHTFIELD_MODEL_H

#define HEIGHTFIELD_MIN_FACING 1e-3f

#endif
