namespace AcDream.Core.Physics;

/// <summary>The rule of <c>PhysicsEngine.AddLandblock</c> an object breaks (<see cref="ObjectRefusedException.Rule"/>).</summary>
public enum ObjectRule
{
    /// <summary>The object stands in a cell (<see cref="ObjectSurface.CellId"/>) that is not among the landblock's cells.</summary>
    CellNotGiven = 1,

    /// <summary>A building's door cell (<see cref="ObjectSurface.DoorCellIds"/>) is not among the landblock's cells.</summary>
    DoorCellNotGiven,

    /// <summary>An outdoor object reaches more than <see cref="PhysicsConstants.MaxSeamReach"/> past the landblock's edges.</summary>
    ReachesPastSeam,
}
