namespace urbis { int placeholderCore = 0; }
