module onpath() cube(12);
