# port/mpi/port.mk: the MPI port (make PORT=mpi) builds with the MPI compiler wrapper (mpicc, or
# MPICC=...) into build/mpi (build/mpi-fixed ...). Its sources are port/mpi/port_mpi.c, the contract,
# and the POSIX port's work, port/posix/posix.c (its functions am_posix_*, which port_mpi.c calls;
# port/posix/port_posix.c, the POSIX contract over them, is not built here).
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
PORT_FILES += port/posix/posix.c
