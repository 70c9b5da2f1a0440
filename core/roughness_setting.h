/* A roughness setting: one perceptual roughness for every surface, or the
 * material's own. The convention of `gtlab render --roughness`, of the
 * references that take it (specular-occlusion, env-specular) and of the
 * screen passes fed from them: a setting below 0 means "the material's"
 * (the references' default, ROUGHNESS_OF_MATERIAL). Decoded here and only
 * here, so the convention cannot drift between its users. */
#ifndef GTLAB_CORE_ROUGHNESS_SETTING_H
#define GTLAB_CORE_ROUGHNESS_SETTING_H

/* The setting that stands for the material's roughness. */
#define ROUGHNESS_OF_MATERIAL (-1.0f)

/* 1 if the setting means the material's roughness, 0 if it is one roughness
 * for every surface. */
static inline int roughness_is_material(double setting)
{
    return setting < 0.0;
}

/* The roughness to use at a surface whose material has `material`. */
static inline double roughness_choose(double setting, double material)
{
    return roughness_is_material(setting) ? material : setting;
}

#endif
