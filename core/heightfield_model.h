/* The height field a depth buffer stands for, shared by the height-field AO
 * reference (raytracer/heightfield_ao_integrator.c) and the screen-space
 * techniques (realtime/screen_space.c), two independent implementations that
 * must agree on what the depth buffer means:
 *  - each pixel is a planar piece: along an eye ray through any point of the
 *    pixel, the surface lies where the ray meets the tangent plane of the
 *    surface seen at the pixel's centre (its position and normal);
 *  - a pixel whose plane is seen at a grazing angle (|n . w| < MIN_FACING for
 *    the unit eye ray w) is a piece facing the camera at the centre's depth
 *    instead: extending a nearly edge-on plane across the pixel would put
 *    phantom surface far above or below it;
 *  - everything behind the surface is solid (infinite thickness). */
#ifndef GTLAB_CORE_HEIGHTFIELD_MODEL_H
#define GTLAB_CORE_HEIGHTFIELD_MODEL_H

#define HEIGHTFIELD_MIN_FACING 0.25f

#endif
