namespace AcDream.Core.Physics;

/// <summary>What a line or triangle handed to an <see cref="IDebugSink"/> is part of, and what its id names.</summary>
public enum DrawKind : byte
{
    /// <summary>A terrain triangle (two per 24 m outdoor cell, split as the landblock's cell is); id: the outdoor cell (<c>0xXXYY0001..0040</c>).</summary>
    Terrain,

    /// <summary>A floor triangle of an indoor cell; id: the cell.</summary>
    CellFloor,

    /// <summary>An edge of a wall (or ceiling) polygon of an indoor cell; id: the cell.</summary>
    CellWall,

    /// <summary>An edge of a doorway or other portal's polygon, on its plane; id: the cell whose portal it is.</summary>
    Portal,

    /// <summary>A floor triangle of an object (or building); id: the object's model id.</summary>
    ObjectFloor,

    /// <summary>An edge of a wall polygon of an object (or building); id: the object's model id.</summary>
    ObjectWall,

    /// <summary>A cylinder of an object: its sides' uprights and its rings' chords, every end on its radius from the axis, at its bottom or top; id: the object's model id.</summary>
    Cylinder,

    /// <summary>An edge of a committed mover's wall polygon, or of its cylinder as <see cref="Cylinder"/>; id: the mover.</summary>
    Mover,

    /// <summary>One sub-step of a move, from where the feet were to where they went (the last ends at the answer); id: the request's mover id.</summary>
    SubStep,

    /// <summary>A contact: from the point where the body (or point) met a wall, along the wall's unit normal, <see cref="PhysicsEngine.DrawNormalLength"/> long; id: the request's mover id.</summary>
    Contact,

    /// <summary>The floor triangle under the answer's centre that it stands on (terrain, a cell's or an object's floor); id: the outdoor cell, cell or object.</summary>
    Floor,

    /// <summary>The floor triangle under the body's footprint that holds it where the ground under its centre does not (footing); id: the cell or object.</summary>
    Support,

    /// <summary>The edge of the floor a body was held at: a segment along the edge through its nearest point, at the feet's height; id: the floor's cell or object.</summary>
    Edge,

    /// <summary>The surface that stopped a rise: from the point over the body's centre where its top met it, along its unit normal (down), <see cref="PhysicsEngine.DrawNormalLength"/> long; id: the request's mover id.</summary>
    Ceiling,
}
