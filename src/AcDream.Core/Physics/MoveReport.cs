using System.Numerics;

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

    /// <summary>A registered mover's walls (<see cref="Movers"/>): the contact's id is the mover's.</summary>
    Mover,

    /// <summary>An indoor cell's polygon facing down (unit normal Z at most −<see cref="PhysicsConstants.FloorZ"/>), as a cast (<see cref="PhysicsEngine.Cast"/>) meets it; the id is the cell's. A move reports a ceiling as <see cref="CellWall"/>.</summary>
    CellCeiling,
}

/// <summary>A surface a move met.</summary>
/// <param name="Kind">What it is.</param>
/// <param name="Id">Whose it is: a cell id or an object's GfxObj/Setup id, as <paramref name="Kind"/> says; 0 with <see cref="SurfaceKind.None"/>.</param>
/// <param name="Normal">Its unit normal, world axes, pointing at the mover's side (a wall's is horizontal, as <see cref="ResolveResult.SurfaceNormal"/>); zero with <see cref="SurfaceKind.None"/>.</param>
public readonly record struct SurfaceContact(SurfaceKind Kind, uint Id, Vector3 Normal);

/// <summary>
/// What one <c>Resolve</c> met: the floor its answer stands on and the wall that stopped or slid it.
/// Filled by <see cref="PhysicsEngine.Resolve(Vector3, uint, Vector3, float, in MovementOptions, out MoveReport)"/>.
/// </summary>
/// <param name="Floor">
/// The ground under the answer when <see cref="ResolveResult.IsOnGround"/> is true: the terrain, the cell's
/// floor or an object's floor the position stands on, with its normal; <see cref="SurfaceKind.None"/> when
/// airborne or held (the land is not loaded).
/// </param>
/// <param name="Wall">
/// When the answer's outcome is <see cref="ResolveOutcome.Wall"/>, <see cref="ResolveOutcome.OuterWall"/> or
/// <see cref="ResolveOutcome.Slid"/> along a wall: the wall, shell or cylinder that stopped or slid the
/// mover, with the answer's <see cref="ResolveResult.SurfaceNormal"/> (zero for a building's outer wall found
/// by the doors-only rule, as there); <see cref="SurfaceKind.None"/> for every other outcome and for a call's
/// limit of cell visits.
/// </param>
public readonly record struct MoveReport(SurfaceContact Floor, SurfaceContact Wall);
