/* amorph.h: the whole public API. */
#ifndef AMORPH_H
#define AMORPH_H
#include "amorph/config.h"
#include "amorph/real.h"
#include "amorph/status.h"
#include "amorph/text.h"
#include "amorph/mathx.h"
#include "amorph/rng.h"
#include "amorph/lattice.h"
#include "amorph/dct.h"
#include "amorph/genotype.h"
#include "amorph/sim.h"
#include "amorph/evolve.h"
#include "amorph/image.h"
#include "amorph/mesh.h"
#include "amorph/inflate.h"
#include "amorph/port.h"
#include "amorph/xml.h"
#include "amorph/vxa.h"
#endif
