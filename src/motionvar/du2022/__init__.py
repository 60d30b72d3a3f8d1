"""Han Du 2022, *Modeling Variation of Human Motion* (PhD thesis): functional data (ch. 3,
``fda``), Morphable Graphs (ch. 4, ``graph``) and the style VAE/CVAE (ch. 5, ``style``)."""
