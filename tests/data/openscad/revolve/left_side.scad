// A profile on the side x < 0, turned by 60 degrees: it starts on -x.
rotate_extrude(angle = 60) translate([-12, 0]) square([4, 4]);
