/* sim_robot.c: a robot as one unit (its lattice, layers, environment and evaluation: am_robot),
 * set to the defaults and built into a model. Above the model build and the evaluation, so
 * neither depends on the other's defaults: am_model_build takes an environment and nothing of how
 * the robot will be evaluated. */
#include "sim_internal.h"

void am_robot_init(am_robot* r, am_lattice* lat, am_layers* layers)
{
    r->lattice = lat;
    r->layers = layers;
    if (layers) am_layers_clear(layers);
    r->env = am_default_env();
    r->eval = am_default_eval();
}

am_status am_robot_build(am_model* m, const am_robot* r, char* err, int errsz)
{
    return am_model_build_layers(m, r->lattice, &r->env, r->layers, err, errsz);
}
