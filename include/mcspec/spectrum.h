/* mcspec spectrum module: declarations land with its implementation. */
#ifndef MCSPEC_SPECTRUM_H
#define MCSPEC_SPECTRUM_H
#endif /* MCSPEC_SPECTRUM_H */
