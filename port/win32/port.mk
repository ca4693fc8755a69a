# port/win32/port.mk: how the Windows port links (included by the Makefile for PORT=win32).
# The program is amorph.exe (the compiler names a Windows program so whatever -o says); the C
# runtime's threads need no library of their own (no -lpthread); make check-alloc reads the
# objects with mingw-w64's nm.
ifeq ($(TARGET),)
$(error PORT=win32 is a cross build: name it with TARGET=win64)
endif
EXE    := .exe
LDLIBS := -lm
NM     := x86_64-w64-mingw32-nm
