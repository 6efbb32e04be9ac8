module inhome() cube(13);
