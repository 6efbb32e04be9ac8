module thing() sphere(5);
module other() thing();
function v() = 5;
