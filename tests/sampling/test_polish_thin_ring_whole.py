"""A ring thinner than the grid spacing, on which no node of the 11-grid is admissible: the polished span
starts from the 16 least-violating nodes and reaches the ring's exact extent (centre +- outer radius) on both
factors; from only 2 d = 4 of them one end of this ring stays short by about 0.24.