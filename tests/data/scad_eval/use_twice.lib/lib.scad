module part() cube(2);
