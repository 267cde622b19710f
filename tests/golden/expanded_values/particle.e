class
	PARTICLE

feature -- Access

	position: VECTOR

	move (v: VECTOR)
		do
			position.set (position.x + v.x, position.y + v.y)
			v.scale (100)
		end

end
