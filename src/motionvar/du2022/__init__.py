"""Han Du 2022, *Modeling Variation of Human Motion* (PhD thesis): functional data (ch. 3,
``du2022_fda``), Morphable Graphs (ch. 4, ``du2022_graph``) and the style VAE/CVAE (ch. 5, ``du2022_style``)."""
