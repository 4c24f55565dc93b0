/* mcspec dft module: declarations land with its implementation. */
#ifndef MCSPEC_DFT_H
#define MCSPEC_DFT_H
#endif /* MCSPEC_DFT_H */
