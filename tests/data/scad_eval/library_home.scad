use <inhome.scad>
inhome();
