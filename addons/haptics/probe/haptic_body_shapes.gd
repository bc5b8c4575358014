extends RefCounted
## A [PhysicsBody2D]'s own collision shapes, read through its shape owners (each
## [CollisionShape2D], and each convex part of a [CollisionPolygon2D]): the solid ones that
## make its outline, and the bounds of all of them. A [HapticProbe] looks above the solid
## ones for objects resting on the body, and reports the body's height from the bounds.
##
## Rays ([SeparationRayShape2D]) and world boundaries are not outline: a platformer's
## downward ray reaches into the floor the body stands on, and objects found "above" it are
## the floor itself.

## Each entry: [code]shape[/code] (Shape2D), [code]transform[/code] (relative to the body),
## [code]owner[/code] (the node that holds it).
var solid: Array[Dictionary] = []
## Shapes skipped as no outline, by their owner's name and class (for the probe's warning).
var skipped: PackedStringArray = []
## The body-local rectangle every enabled shape (rays too) lies in; empty without shapes.
var bounds: Rect2 = Rect2()


func _init(p_body: CollisionObject2D) -> void:
	var first: bool = true
	for owner_id: int in p_body.get_shape_owners():
		if p_body.is_shape_owner_disabled(owner_id):
			continue
		var owner: Object = p_body.shape_owner_get_owner(owner_id)
		var local: Transform2D = p_body.shape_owner_get_transform(owner_id)
		for i: int in p_body.shape_owner_get_shape_count(owner_id):
			var shape: Shape2D = p_body.shape_owner_get_shape(owner_id, i)
			var rect: Rect2 = local * _extent(shape)
			bounds = rect if first else bounds.merge(rect)
			first = false
			if shape is SeparationRayShape2D or shape is WorldBoundaryShape2D:
				var node: Node = owner as Node
				var owner_name: String = str(node.name) if node != null else "?"
				skipped.append("%s (%s)" % [owner_name, shape.get_class()])
				continue
			solid.append({"shape": shape, "transform": local, "owner": owner})


# Where [param shape] reaches, in its own space: a ray's segment exactly (its own rect is
# padded), any other shape's rect.
static func _extent(shape: Shape2D) -> Rect2:
	var ray: SeparationRayShape2D = shape as SeparationRayShape2D
	if ray != null:
		return Rect2(Vector2.ZERO, Vector2(0.0, ray.length))
	return shape.get_rect()
