namespace AcDream.Core.Physics;

/// <summary>What a surface a move met is: see <see cref="SurfaceContact.Kind"/>.</summary>
public enum SurfaceKind : byte
{
    /// <summary>Nothing: no floor under the answer (airborne, or held over land not loaded), or no wall met.</summary>
    None = 0,

    /// <summary>The terrain; the id is the outdoor cell (<c>0xXXYY00CC</c>).</summary>
    Terrain,

    /// <summary>An indoor cell's floor; the id is the cell's.</summary>
    CellFloor,

    /// <summary>An object's floor (a step, a tread, a plinth); the id is the object's GfxObj or Setup id.</summary>
    ObjectFloor,

    /// <summary>An indoor cell's wall, or a building's cell entered other than by a door (doors only); the id is the cell's.</summary>
    CellWall,

    /// <summary>A wall polygon of an object that is not a building; the id is the object's GfxObj or Setup id.</summary>
    ObjectWall,

    /// <summary>A wall of a building's shell (<see cref="ObjectSurface.IsBuilding"/>); the id is the shell's GfxObj or Setup id.</summary>
    BuildingShell,

    /// <summary>An object's cylinder (a tree's trunk, a post); the id is the object's GfxObj or Setup id.</summary>
    Cylinder,

    /// <summary>The edge of a floor the body stood on and would have stepped off (edge slide); the id is the floor's: a cell's, or an object's GfxObj or Setup id (0 for the terrain's ground).</summary>
    FloorEdge,

    /// <summary>A registered mover's walls (<see cref="MoverRegistry"/>): the contact's id is the mover's.</summary>
    Mover,

    /// <summary>An indoor cell's polygon facing down (unit normal Z at most −<see cref="PhysicsConstants.FloorZ"/>), as a cast (<see cref="PhysicsEngine.Cast"/>) meets it; the id is the cell's. A move reports a ceiling as <see cref="CellWall"/>.</summary>
    CellCeiling,
}
