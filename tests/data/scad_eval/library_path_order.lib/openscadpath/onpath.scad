module onpath() cube(11);
