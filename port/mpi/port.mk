# port/mpi/port.mk: the MPI port (make PORT=mpi) builds with the MPI compiler wrapper (mpicc, or
# MPICC=...) into build/mpi (build/mpi-fixed ...). Its sources are port/mpi/ only: posix_base.c
# compiles port/posix/port_posix.c under other names, so that file is a dependency here.
MPICC ?= mpicc
ifneq ($(origin CC),command line)
CC := $(MPICC)
endif
ifneq ($(origin BUILD),command line)
BUILD := build/mpi$(if $(filter-out float,$(REAL)),-$(REAL))$(if $(filter-out desktop,$(PROFILE)),-$(PROFILE))
endif
ifeq ($(shell command -v $(firstword $(CC)) 2>/dev/null),)
$(error PORT=mpi needs an MPI compiler wrapper: '$(CC)' not found (Debian: apt-get install libopenmpi-dev openmpi-bin))
endif
.DEFAULT_GOAL := all
$(BUILD)/port/mpi/posix_base.o: port/posix/port_posix.c
