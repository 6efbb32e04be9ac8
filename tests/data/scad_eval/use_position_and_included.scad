$fn = 7;
bolt(3);
include <use_position_and_included.lib/inc.scad>
nut();
use <use_position_and_included.lib/bolt.scad>
