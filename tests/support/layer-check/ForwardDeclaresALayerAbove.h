// A geometry file that names the object layer's class without including its header: a
// forward declaration gets past the include check, so the layer check must refuse it too.
class GameObject;
