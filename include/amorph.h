/* amorph.h: the whole public API. */
#ifndef AMORPH_H
#define AMORPH_H
#include "amorph/base.h"
#include "amorph/sim.h"
#include "amorph/geno.h"
#include "amorph/evo.h"
#include "amorph/io.h"
#include "amorph/api.h"
#endif
