sphere(d = 5); circle(d = 3); sphere(); circle();
